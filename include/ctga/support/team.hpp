// A team of threads that work through index ranges together (fork–join), made once and reused:
//
//   ctga::team crew(2);                                   // the caller and one more thread
//   crew.run(n, [&](std::size_t begin, std::size_t end) { for (std::size_t i = begin; i < end; ++i) work(i); });
//
// run splits [0, n) into one contiguous chunk per thread (the caller takes the first) and returns
// when every chunk is done. No allocation after construction: the work is passed by reference
// (a function pointer and the caller's object), the threads wait on an atomic generation count
// (C++20 wait/notify) between runs. Which thread does which chunk changes nothing a caller can see
// as long as chunks do not share what they write: results do not depend on the number of threads.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <thread>
#include <vector>

namespace ctga {

class team {
public:
    // threads ≥ 1 (1: the caller alone, no thread started).
    explicit team(std::size_t threads = 1) : size_(threads > 0 ? threads : 1) {
        workers_.reserve(size_ - 1);
        for (std::size_t t = 1; t < size_; ++t) workers_.emplace_back([this, t] { serve(t); });
    }
    team(const team&) = delete;
    team& operator=(const team&) = delete;
    ~team() {
        stop_.store(true, std::memory_order_relaxed);
        generation_.fetch_add(1, std::memory_order_release);
        generation_.notify_all();
        for (std::thread& w : workers_) w.join();
    }

    [[nodiscard]] std::size_t size() const noexcept { return size_; }

    // f(begin, end) on each thread's chunk of [0, n).
    template <class F>
    void run(std::size_t n, F&& f) {
        if (size_ == 1 || n < 2 * size_) return f(std::size_t{0}, n);
        run_parts(n, f);
    }
    // The same for n ≥ 1 items of any number: a few large parts (each thread's chunk may be empty).
    template <class F>
    void run_parts(std::size_t n, F&& f) {
        if (size_ == 1 || n < 2) return f(std::size_t{0}, n);
        using G = std::remove_reference_t<F>;
        job_ = &call<G>;
        context_ = const_cast<void*>(static_cast<const void*>(&f));  // call<G> restores G, const or not
        count_ = n;
        pending_.store(static_cast<std::uint32_t>(size_ - 1), std::memory_order_relaxed);
        generation_.fetch_add(1, std::memory_order_release);
        generation_.notify_all();
        f(std::size_t{0}, chunk_end(0));
        for (int spin = 0; spin < spins && pending_.load(std::memory_order_acquire) != 0; ++spin) {}
        for (std::uint32_t left = pending_.load(std::memory_order_acquire); left != 0; left = pending_.load(std::memory_order_acquire))
            pending_.wait(left, std::memory_order_acquire);
    }

private:
    template <class F>
    static void call(void* context, std::size_t begin, std::size_t end) {
        (*static_cast<F*>(context))(begin, end);  // F may be const-qualified
    }
    [[nodiscard]] std::size_t chunk_end(std::size_t t) const noexcept { return count_ * (t + 1) / size_; }
    void serve(std::size_t t) {
        std::uint32_t seen = 0;
        for (;;) {
            // a short spin first: runs come in quick succession (a solver's sweeps, two or three a
            // sweep). 2¹⁸ loads, about 0.1 ms; with 2¹⁴ the threads slept between a pile's phases
            // (1,000 bodies, 3,900 contacts: each phase about 50 µs) and two ran slower than one.
            for (int spin = 0; spin < spins && generation_.load(std::memory_order_acquire) == seen; ++spin) {}
            generation_.wait(seen, std::memory_order_acquire);
            seen = generation_.load(std::memory_order_acquire);
            if (stop_.load(std::memory_order_relaxed)) return;
            job_(context_, count_ * t / size_, chunk_end(t));
            if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
        }
    }

    static constexpr int spins = 1 << 18;
    std::size_t size_;
    std::vector<std::thread> workers_;
    std::atomic<std::uint32_t> generation_{0}, pending_{0};
    std::atomic<bool> stop_{false};
    void (*job_)(void*, std::size_t, std::size_t) = nullptr;
    void* context_ = nullptr;
    std::size_t count_ = 0;
};

}  // namespace ctga
