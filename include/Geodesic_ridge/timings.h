// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one place where the algorithms' time is measured: their drivers run each
// named step through `Timings::time`, and the statistics keep only counts.
#ifndef GEODESIC_RIDGE_TIMINGS_H
#define GEODESIC_RIDGE_TIMINGS_H

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// Seconds spent per named step of an algorithm, in the order the steps were
/// first timed. A step timed inside another one is not counted in the outer
/// one (exclusive times), so the steps add up to the time of the whole.
class Timings
{
public:
  /// Runs `f()`, adds the seconds it took (less those of the steps timed
  /// inside it) to `step`, and returns what `f()` returns.
  template <class F>
  decltype(auto) time(const std::string& step, F&& f)
  {
    const Clock_guard guard(*this, step);
    return f();
  }

  /// the seconds of `step`; 0 if it was never timed
  double operator[](const std::string& step) const
  {
    for(const auto& s : steps_)
      if(s.first == step) return s.second;
    return 0;
  }

  /// every step timed, with its seconds, in the order first timed
  const std::vector<std::pair<std::string, double> >& steps() const { return steps_; }

  /// the seconds of all steps together
  double total() const
  {
    double sum = 0;
    for(const auto& s : steps_) sum += s.second;
    return sum;
  }

private:
  typedef std::chrono::steady_clock Clock;

  // Stops the clock of a step when it leaves scope (also by an exception).
  struct Clock_guard
  {
    Timings& timings;
    const std::string& step;
    const Clock::time_point start = Clock::now();
    Clock_guard(Timings& t, const std::string& s) : timings(t), step(s) { timings.nested_.push_back(0); }
    ~Clock_guard()
    {
      const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      const double inner = timings.nested_.back();
      timings.nested_.pop_back();
      timings.add(step, elapsed - inner);
      if(!timings.nested_.empty()) timings.nested_.back() += elapsed;
    }
  };

  void add(const std::string& step, double seconds)
  {
    for(auto& s : steps_)
      if(s.first == step) { s.second += seconds; return; }
    steps_.emplace_back(step, seconds);
  }

  std::vector<std::pair<std::string, double> > steps_;
  std::vector<double> nested_; // per running step: the seconds of the steps timed inside it
};

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_TIMINGS_H
