// A progress line on standard error for the long commands (--frames, batch,
// test): "[#####.........]  12/40 frames, 1 failed, 0:07 left", redrawn in
// place, and only when standard error is a terminal, so that logs and pipes
// get no carriage returns.
#pragma once
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace glslrun::cli {

class Progress {
public:
    Progress(std::string noun, size_t total);
    ~Progress();  // ends the line
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void step(bool failed = false);
    // Prints a whole line (a failure's message) to `to` above the progress line.
    void print(const std::string& text, std::FILE* to = stderr);
    bool active() const { return active_; }

private:
    void draw();
    void clear();
    std::string noun_;
    size_t total_, done_ = 0, failed_ = 0;
    bool active_;
    std::chrono::steady_clock::time_point start_;
};

// "0:07", "1:02:03": the time left after `done` of `total` took `elapsed` seconds.
std::string format_eta(double elapsed, size_t done, size_t total);

}  // namespace glslrun::cli
