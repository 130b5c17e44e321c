// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer entry point of the command-line options target (bash scripts/fuzz.sh options SECONDS).

#define GR_FUZZ_CLI
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* d, size_t n) { return gr_fuzz::fuzz_options(d, n); }
