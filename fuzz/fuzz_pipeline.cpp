// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer entry point of the pipeline target (bash scripts/fuzz.sh pipeline SECONDS).

#define GR_FUZZ_PIPELINE
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* d, size_t n) { return gr_fuzz::fuzz_pipeline(d, n); }
