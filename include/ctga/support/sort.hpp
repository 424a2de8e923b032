// Sorting for constant evaluation, without <algorithm> (which, with <vector>, is a third of the
// core headers' parse time): a bottom-up merge sort, stable, n log n comparisons, through one
// transient buffer (constexpr new, C++20). Used only while building tables at compile time.
#pragma once

#include <cstddef>

namespace ctga::detail {

template <class T, class Less>
constexpr void merge_sort(T* first, std::size_t n, Less less) {
    if (n < 2) return;
    // runs of 8 by insertion
    constexpr std::size_t run = 8;
    for (std::size_t b = 0; b < n; b += run) {
        const std::size_t e = b + run < n ? b + run : n;
        for (std::size_t i = b + 1; i < e; ++i) {
            T x = first[i];
            std::size_t j = i;
            for (; j > b && less(x, first[j - 1]); --j) first[j] = first[j - 1];
            first[j] = x;
        }
    }
    if (n <= run) return;
    T* buffer = new T[n];
    T* from = first;
    T* to = buffer;
    for (std::size_t width = run; width < n; width *= 2) {
        for (std::size_t b = 0; b < n; b += 2 * width) {
            const std::size_t m = b + width < n ? b + width : n;
            const std::size_t e = b + 2 * width < n ? b + 2 * width : n;
            std::size_t i = b, j = m, k = b;
            while (i < m && j < e) to[k++] = less(from[j], from[i]) ? from[j++] : from[i++];
            while (i < m) to[k++] = from[i++];
            while (j < e) to[k++] = from[j++];
        }
        T* t = from;
        from = to;
        to = t;
    }
    if (from != first)
        for (std::size_t i = 0; i < n; ++i) first[i] = from[i];
    delete[] buffer;
}

}  // namespace ctga::detail
