// EXPECT: ctga: sample failure
// Sample compile-fail test (proves the mechanism; delete once real ones exist).
static_assert(sizeof(int) == 0, "ctga: sample failure");
