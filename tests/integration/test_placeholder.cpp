// SPDX-License-Identifier: MIT
// (replaced by the assembly tests)
#include <gtest/gtest.h>
