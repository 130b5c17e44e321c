// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3's switches: every pass that is not needed for a ridge to exist (and
// every spur rule) can be switched off, so that the effect its comment claims
// can be measured again without editing code (`bench_ridge_accuracy --without
// NAME`; the named parameter `disabled_ridge_passes`). All are on by default.
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RIDGE_PASSES_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RIDGE_PASSES_H

#include <array>
#include <string>
#include <utility>

namespace Geodesic_ridge {
namespace internal {

// (the passes that always run: the envelopes, the segments inside faces and
// along edges, the merge into one region, the main component and its count)
enum class Ridge_pass : unsigned
{
  recombined_copy_split = 1u << 0,    // `Recombined_copy_splitter`
  kink_split = 1u << 1,               // `Kink_splitter` (also off with `kink_angle(0)`)
  thin_faces = 1u << 2,               // `thin_faces`: no face is thin
  rejoin_pieces = 1u << 3,            // `rejoin_pieces`
  spur_at_impossible_end = 1u << 4,   // the spur rules (`Spur_pruning`; all off with `minimum_spur_angle(0)`)
  spur_away_from_corner = 1u << 5,
  spur_too_weak_for_corner = 1u << 6,
  spur_flat_end = 1u << 7,
  join_border_components = 1u << 8,   // `join_border_components`
  join_verified_pieces = 1u << 9      // `join_verified_pieces`
};

// the name of every switch, as `bench_ridge_accuracy --without` takes it
inline const std::array<std::pair<const char*, Ridge_pass>, 10>& ridge_pass_names()
{
  static const std::array<std::pair<const char*, Ridge_pass>, 10> names = {{
      {"recombined-copy-split", Ridge_pass::recombined_copy_split},
      {"kink-split", Ridge_pass::kink_split},
      {"thin-faces", Ridge_pass::thin_faces},
      {"rejoin-pieces", Ridge_pass::rejoin_pieces},
      {"spur-at-impossible-end", Ridge_pass::spur_at_impossible_end},
      {"spur-away-from-corner", Ridge_pass::spur_away_from_corner},
      {"spur-too-weak-for-corner", Ridge_pass::spur_too_weak_for_corner},
      {"spur-flat-end", Ridge_pass::spur_flat_end},
      {"join-border-components", Ridge_pass::join_border_components},
      {"join-verified-pieces", Ridge_pass::join_verified_pieces}}};
  return names;
}

// Which passes run: a bit per switched-off pass (`Ridge_pass`).
struct Ridge_passes
{
  unsigned disabled = 0;
  bool on(Ridge_pass p) const { return (disabled & static_cast<unsigned>(p)) == 0; }
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RIDGE_PASSES_H
