#include <ctga/ctga.hpp>

#include <cstdio>

static_assert(__cplusplus >= 202002L, "ctga::ctga must bring C++20");

int main() {
    std::puts("ok");
    return 0;
}
