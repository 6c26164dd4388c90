// Work on several threads whose outcome does not depend on their number: parallelFor stores each
// index's result by index, and the callers reduce in index order. Shared by `run`
// (campaign/fold.cpp) and `search` (search.cpp).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace gjkval
{

// --threads: 0 means every core.
inline int resolveThreads(int requested)
{
    return requested > 0 ? requested : int(std::max(1u, std::thread::hardware_concurrency()));
}

// Progress bar on stderr (only when it is a terminal and asked for).
class Progress
{
  public:
    Progress(bool enabled, std::string label, std::size_t total)
        : enabled_(enabled), label_(std::move(label)), total_(total)
    {
        if (enabled_)
            thread_ = std::thread([this] { loop(); });
    }
    // A progress that draws nothing: for the phases whose progress is not shown.
    static Progress silent() { return Progress(false, "", 0); }
    ~Progress()
    {
        if (!enabled_)
            return;
        {
            std::lock_guard lock(m_);
            stop_ = true;
        }
        cv_.notify_all();
        thread_.join();
        draw();
        std::fputc('\n', stderr);
    }
    void add(std::size_t n) { done_ += n; }
    // More to do than the total said: an input counted as it is read.
    void grow(std::size_t n) { total_ += n; }

  private:
    void loop()
    {
        std::unique_lock lock(m_);
        while (!cv_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; }))
            draw();
    }
    void draw()
    {
        const std::size_t total = total_.load();
        const std::size_t d = std::min(done_.load(), total);
        const int width = 40;
        const int fill = total ? int(double(d) / double(total) * width) : width;
        std::fprintf(stderr, "\r%-8s [%s%s] %zu/%zu", label_.c_str(),
                     std::string(std::size_t(fill), '#').c_str(),
                     std::string(std::size_t(width - fill), ' ').c_str(), d, total);
        std::fflush(stderr);
    }
    bool enabled_;
    std::string label_;
    std::atomic<std::size_t> total_;
    std::atomic<std::size_t> done_{0};
    std::thread thread_;
    std::mutex m_;
    std::condition_variable cv_;
    bool stop_ = false;
};

// fn(i) for i in [0, n) on `threads` threads, in chunks; each index is computed exactly once and
// results are stored by index, so the outcome does not depend on the thread count.
template <class F> inline void parallelFor(std::size_t n, int threads, Progress& progress, F fn)
{
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex errorMutex;
    const std::size_t chunk = 8;
    auto worker = [&]
    {
        for (;;)
        {
            const std::size_t start = next.fetch_add(chunk);
            if (start >= n)
                break;
            const std::size_t end = std::min(n, start + chunk);
            try
            {
                for (std::size_t i = start; i < end; ++i)
                    fn(i);
            }
            catch (...)
            {
                std::lock_guard lock(errorMutex);
                if (!error)
                    error = std::current_exception();
            }
            progress.add(end - start);
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(worker);
    worker();
    for (auto& t : pool)
        t.join();
    if (error)
        std::rethrow_exception(error);
}

} // namespace gjkval
