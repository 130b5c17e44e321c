// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test helper: the message of the exception a call throws.
#ifndef GEODESIC_RIDGE_TEST_SUPPORT_MESSAGE_OF_H
#define GEODESIC_RIDGE_TEST_SUPPORT_MESSAGE_OF_H

#include <catch2/catch.hpp>

#include <exception>
#include <string>

namespace Geodesic_ridge {
namespace testing {

// The message of the exception of type E thrown by f; fails the test if f
// throws nothing or another type.
template <class E, class F>
std::string message_of(F&& f)
{
  try
  {
    f();
  }
  catch(const E& e)
  {
    return e.what();
  }
  catch(const std::exception& e)
  {
    FAIL("expected another exception type, got: " << e.what());
  }
  FAIL("no exception thrown");
  return {};
}

} // namespace testing
} // namespace Geodesic_ridge

#endif
