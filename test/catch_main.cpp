// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The Catch2 main function, compiled once for every test program.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
