#include "experiments/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdlib>
#include <iostream>

#include <fmt/format.h>

namespace fb89::experiments {

namespace {
constexpr uint64_t kEveryUnitUpTo = 1000;

thread_local const ProgressObserver* current_observer = nullptr;

std::size_t code_points(std::string_view text) {
    std::size_t n = 0;
    for (const char c : text)
        n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
}

}  // namespace

std::string fit_to_width(const std::string& text, std::size_t columns) {
    const std::size_t room = columns > 1 ? columns - 1 : 1;
    if (code_points(text) <= room) return text;
    const std::string mark = "...";
    if (room <= mark.size()) return mark.substr(0, room);
    // keep the last (room - 3) code points
    std::size_t keep = room - mark.size(), start = text.size();
    while (start > 0 && keep > 0) {
        --start;
        if ((static_cast<unsigned char>(text[start]) & 0xC0) != 0x80) --keep;
    }
    return mark + text.substr(start);
}

std::size_t terminal_columns() {
    winsize size{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    if (const char* columns = std::getenv("COLUMNS")) {
        const long n = std::strtol(columns, nullptr, 10);
        if (n > 0 && n < 100000) return static_cast<std::size_t>(n);
    }
    return 80;
}

ObserveProgress::ObserveProgress(ProgressObserver observer)
    : m_before(current_observer), m_observer(std::move(observer)) {
    current_observer = m_observer ? &m_observer : nullptr;
}

ObserveProgress::~ObserveProgress() {
    current_observer = m_before;
}

ProgressLine::ProgressLine(bool on) : m_on(on), m_observer(current_observer) {}

void ProgressLine::start(std::string what) {
    m_what = std::move(what);
    m_start = std::chrono::steady_clock::now();
    m_last_shown = {};
    if (m_observer) (*m_observer)(m_what, 0, 0, {});
    if (m_on) show(m_what);
}

double ProgressLine::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

void ProgressLine::step(uint64_t done, uint64_t total, std::string_view unit) {
    if (!m_on && !m_observer) return;
    const auto now = std::chrono::steady_clock::now();
    // few units (rounds, scenes): every one; many (rows, pairs): ten times a second at most
    if (total > kEveryUnitUpTo && done < total &&
        now - m_last_shown < std::chrono::milliseconds(100))
        return;
    m_last_shown = now;
    if (m_observer) (*m_observer)(m_what, done, total, unit);
    if (!m_on) return;
    std::string text =
        unit.empty()
            ? fmt::format("{}: {:.0f}%", m_what,
                          total > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total)
                                    : 100.0)
            : fmt::format("{}: {}/{} {}", m_what, done, total, unit);
    if (done > 0 && done < total)
        text += fmt::format(", about {:.0f} s left", seconds() / static_cast<double>(done) *
                                                         static_cast<double>(total - done));
    show(text);
}

void ProgressLine::show(const std::string& full) {
    const std::string text = fit_to_width(full, terminal_columns());
    const std::size_t width = code_points(text);
    std::lock_guard lock(m_out);
    const std::size_t pad = m_width > width ? m_width - width : 0;
    std::cerr << '\r' << text << std::string(pad, ' ') << std::flush;
    m_width = width;
}

void ProgressLine::clear() {
    if (!m_on) return;
    std::lock_guard lock(m_out);
    if (m_width == 0) return;
    std::cerr << '\r' << std::string(m_width, ' ') << '\r' << std::flush;
    m_width = 0;
}

ProgressLine::Ticker::Ticker(ProgressLine& l) : line(l) {
    thread = std::thread([this] {
        std::unique_lock lock(mutex);
        while (!wake.wait_for(lock, std::chrono::seconds(1), [this] { return stop; }))
            line.show(fmt::format("{}: {:.0f} s", line.m_what, line.seconds()));
    });
}

ProgressLine::Ticker::~Ticker() {
    {
        std::lock_guard lock(mutex);
        stop = true;
    }
    wake.notify_one();
    thread.join();
}

}  // namespace fb89::experiments
