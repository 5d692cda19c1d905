// One line of progress on stderr, rewritten in place: what is running, how far it has got,
// and an estimate of the time left. A line that is off prints nothing: the commands turn it
// on when stderr is a terminal and -q is not given, so pipes and logs stay clean.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace fb89::experiments {

// `text` cut to fit `columns` terminal columns less one (so the cursor never wraps), counted in
// UTF-8 code points: what is cut is the start of the text, marked by "...", since its end says
// how far the work has got.
std::string fit_to_width(const std::string& text, std::size_t columns);

// The width of the terminal on stderr; else $COLUMNS; else 80.
std::size_t terminal_columns();

// Someone other than a person at a terminal following long work (the Python module's
// progress= callbacks): told of each piece of work as it starts (done = total = 0) and of each
// step, as the line would show them. It may throw to stop the work.
using ProgressObserver = std::function<void(const std::string& what, uint64_t done, uint64_t total,
                                            std::string_view unit)>;

// Sets the observer of the progress lines this thread makes while it lives (each line keeps
// its observer, whatever thread then steps it); the one before is put back after.
class ObserveProgress {
  public:
    explicit ObserveProgress(ProgressObserver observer);
    ~ObserveProgress();
    ObserveProgress(const ObserveProgress&) = delete;
    ObserveProgress& operator=(const ObserveProgress&) = delete;

  private:
    const ProgressObserver* m_before;
    ProgressObserver m_observer;
};

class ProgressLine {
  public:
    // `on`: shown on stderr. A line is also told to the thread's observer, if any.
    explicit ProgressLine(bool on);
    ~ProgressLine() { clear(); }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    bool on() const { return m_on; }
    // New work named `what` ("scenes/A.json", "radiosity: form factors"); its clock starts.
    void start(std::string what);
    // `done` of `total` units of the current work: "what: 3/11 rounds, about 12 s left"
    // with a unit, "what: 43%, about 12 s left" without. The estimate is the time so far
    // scaled by what is left; none before the first unit is done. With up to 1000 units
    // every step is drawn; with more, at most ten a second, and always when done == total.
    void step(uint64_t done, uint64_t total, std::string_view unit = {});
    // Runs `work`, showing "what: 12 s" once a second while it runs: for work that has no
    // measure of its own (one emulated run).
    template <class Work>
    auto ticking(Work&& work) {
        if (!m_on) return work();
        Ticker ticker(*this);
        return work();
    }
    // Wipes the line.
    void clear();

  private:
    struct Ticker {
        explicit Ticker(ProgressLine& line);
        ~Ticker();
        ProgressLine& line;
        std::mutex mutex;
        std::condition_variable wake;
        bool stop = false;
        std::thread thread;
    };
    void show(const std::string& text);
    double seconds() const;

    bool m_on;
    const ProgressObserver* m_observer;
    std::string m_what;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point m_last_shown{};
    std::size_t m_width = 0;  // of the text on the line now, in code points
    std::mutex m_out;
};

}  // namespace fb89::experiments
