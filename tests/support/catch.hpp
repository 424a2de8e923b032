// Catch2 v2/v3 compatibility: tests include "support/catch.hpp", never Catch2 directly.
// CTGA_CATCH2_MAJOR (2 or 3) is defined by tests/CMakeLists.txt; __has_include is the fallback.
#pragma once

#if defined(CTGA_CATCH2_MAJOR) && CTGA_CATCH2_MAJOR >= 3
#include <catch2/catch_all.hpp>
#elif defined(CTGA_CATCH2_MAJOR)
#include <catch2/catch.hpp>
#elif __has_include(<catch2/catch_all.hpp>)
#define CTGA_CATCH2_MAJOR 3
#include <catch2/catch_all.hpp>
#elif __has_include(<catch2/catch.hpp>)
#define CTGA_CATCH2_MAJOR 2
#include <catch2/catch.hpp>
#else
#error "ctga tests: Catch2 (v2 or v3) not found"
#endif

#if CTGA_CATCH2_MAJOR >= 3
// v2 has a global Approx; v3 only Catch::Approx. Make `Approx(x)` work with both.
using Catch::Approx;
#endif
