// Test files compiled in parts. A test file whose header has a line `// PARTS: K` is compiled as
// K translation units of one executable (tests/CMakeLists.txt, ctga_test_parts): unit k defines
// CTGA_TEST_PART = k, CTGA_TEST_PARTS = K and CTGA_TEST_PART_NAME = " (part k+1 of K)", then
// includes the file. Without the header the file is one unit, part 0 of 1. What a part holds:
//   - the property suites (support/properties.hpp): work items k, k + K, k + 2K, …
//   - any file: blocks guarded by `#if CTGA_TEST_PART_HOLDS(b)` (block b goes to part b mod K).
// Keeps each unit's compile time and memory in budget: what a CI runner and an editor feel.
#pragma once

#ifndef CTGA_TEST_PART
#define CTGA_TEST_PART 0
#define CTGA_TEST_PARTS 1
#define CTGA_TEST_PART_NAME ""
#endif

#define CTGA_TEST_PART_HOLDS(block) ((block) % CTGA_TEST_PARTS == CTGA_TEST_PART)
