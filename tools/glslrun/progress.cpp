#include "progress.h"

#include <unistd.h>

#include <cstdio>

#include <fmt/format.h>

namespace glslrun::cli {

std::string format_eta(double elapsed, size_t done, size_t total) {
    if (done == 0 || done >= total || !(elapsed >= 0)) return "";
    double left = elapsed / double(done) * double(total - done);
    auto s = static_cast<long long>(left + 0.5);
    if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
    return fmt::format("{}:{:02}", s / 60, s % 60);
}

Progress::Progress(std::string noun, size_t total)
    : noun_(std::move(noun)), total_(total), active_(isatty(fileno(stderr)) == 1),
      start_(std::chrono::steady_clock::now()) {
    if (active_) draw();
}

Progress::~Progress() {
    if (active_) std::fputc('\n', stderr);
}

void Progress::step(bool failed) {
    ++done_;
    if (failed) ++failed_;
    if (active_) draw();
}

void Progress::clear() { std::fputs("\r\033[K", stderr); }

void Progress::print(const std::string& text, std::FILE* to) {
    if (active_) {
        clear();
        std::fflush(stderr);
    }
    std::fputs(text.c_str(), to);
    if (!text.empty() && text.back() != '\n') std::fputc('\n', to);
    std::fflush(to);
    if (active_) draw();
}

void Progress::draw() {
    constexpr size_t kWidth = 30;
    size_t filled = total_ ? done_ * kWidth / total_ : kWidth;
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string eta = format_eta(elapsed, done_, total_);
    clear();
    std::fputs(fmt::format("[{}] {}/{} {}{}{}", bar, done_, total_, noun_,
                           failed_ ? fmt::format(", {} failed", failed_) : "", eta.empty() ? "" : ", " + eta + " left")
                   .c_str(),
               stderr);
    std::fflush(stderr);
}

}  // namespace glslrun::cli
