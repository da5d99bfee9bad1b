// `glslrun serve a.vert a.frag scene.toml`: the shader debugger as a page in
// the browser, on 127.0.0.1 only. The one translation unit that includes
// cpp-httplib (Debian's libcpp-httplib-dev: its header declares, the shared
// library holds the code). What the page shows is computed by ServeSession.
//
// Security, for a viewer of one user's files: the socket is bound to the
// loopback address; requests must name it as their Host (a page elsewhere
// that rebinds a DNS name to 127.0.0.1 is refused) and a POST from another
// origin is refused; the page's own files are read into memory at start and
// served by exact name, so no request path ever reaches the file system;
// edits stay in memory and images go into a scratch directory that is
// removed at exit; every render, trace and search has a time limit.
#include "serve_command.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <httplib.h>
#include <pthread.h>

#include "command_line.h"
#include "render_command.h"
#include "scene/text_file.h"
#include "serve_session.h"

namespace glslrun::cli {
namespace {

namespace fs = std::filesystem;

int fail(const Error& e, int status) {
    std::fputs(e.str().c_str(), stderr);
    return status;
}

// A directory of its own under $TMPDIR, removed with everything in it.
class ScratchDir {
public:
    static Result<ScratchDir> create() {
        std::error_code ec;
        fs::path base = fs::temp_directory_path(ec);
        if (ec) base = "/tmp";
        std::string pattern = (base / "glslrun-serve-XXXXXX").string();
        if (!mkdtemp(pattern.data())) return Error(fmt::format("cannot create a scratch directory in {}", base.string()));
        return ScratchDir(pattern);
    }
    ScratchDir(ScratchDir&& other) noexcept : path_(std::exchange(other.path_, {})) {}
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    ScratchDir& operator=(ScratchDir&&) = delete;
    ~ScratchDir() {
        std::error_code ec;
        if (!path_.empty()) fs::remove_all(path_, ec);
    }
    const std::string& path() const { return path_; }

private:
    explicit ScratchDir(std::string path) : path_(std::move(path)) {}
    std::string path_;
};

struct PageFile {
    std::string content, type;
};

const char* content_type(const fs::path& name) {
    static const std::map<std::string, const char*> kTypes = {
        {".html", "text/html; charset=utf-8"}, {".css", "text/css; charset=utf-8"},
        {".js", "text/javascript; charset=utf-8"}, {".png", "image/png"}, {".svg", "image/svg+xml"}};
    auto it = kTypes.find(name.extension().string());
    return it == kTypes.end() ? "application/octet-stream" : it->second;
}

// The page's files by URL path ("/index.html", and "/" for it), read once:
// only the regular files directly in `dir`.
Result<std::map<std::string, PageFile>> read_page(const std::string& dir) {
    std::map<std::string, PageFile> files;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        if (!e.is_regular_file(ec)) continue;
        std::ifstream in(e.path(), std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (!in) return Error("cannot read the page's file", e.path().string());
        files["/" + e.path().filename().string()] = {text.str(), content_type(e.path())};
    }
    if (ec || !files.contains("/index.html")) return Error("the page's files are missing (index.html)", dir);
    files["/"] = files["/index.html"];
    return files;
}

std::string read_binary(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Host must be the address the server is bound to (or localhost with its
// port), and a request that names an Origin must come from the page itself.
bool from_this_page(const httplib::Request& req, int port) {
    const std::string host = req.get_header_value("Host");
    const std::string a = fmt::format("127.0.0.1:{}", port), b = fmt::format("localhost:{}", port);
    if (host != a && host != b) return false;
    const std::string origin = req.get_header_value("Origin");
    return origin.empty() || origin == "http://" + a || origin == "http://" + b;
}

void set_json(httplib::Response& res, const std::string& text) {
    res.set_content(text, "application/json");
}

void add_routes(httplib::Server& server, ServeSession& session, std::mutex& mutex,
                const std::map<std::string, PageFile>& page) {
    // One user, one session: requests are answered one at a time.
    auto locked = [&](auto handler) {
        return [&, handler](const httplib::Request& req, httplib::Response& res) {
            std::lock_guard lock(mutex);
            handler(req, res);
        };
    };
    server.Get("/api/files", locked([&](const auto&, auto& res) { set_json(res, session.files_json()); }));
    server.Post(R"(/api/files/(\d{1,6}))", locked([&](const auto& req, auto& res) {
        if (!session.set_text(std::stoul(req.matches[1].str()), req.body)) {
            res.status = 404;
            return;
        }
        set_json(res, session.render_json());
    }));
    server.Post("/api/render", locked([&](const auto&, auto& res) { set_json(res, session.render_json()); }));
    server.Get("/api/image.png", locked([&](const auto&, auto& res) {
        if (session.image_png().empty()) res.status = 404;
        else res.set_content(read_binary(session.image_png()), "image/png");
    }));
    server.Get("/api/trace", locked([&](const auto& req, auto& res) {
        auto pixel = parse_int_pair(req.get_param_value("x") + "," + req.get_param_value("y"), ",");
        if (!pixel) {
            res.status = 400;
            return;
        }
        set_json(res, session.trace_json(pixel->first, pixel->second));
    }));
    server.Get("/api/findings", locked([&](const auto&, auto& res) { set_json(res, session.findings_json()); }));
    server.Get("/api/heat", locked([&](const auto&, auto& res) { set_json(res, session.heat_json()); }));
    server.Get("/api/heat.png", locked([&](const auto&, auto& res) {
        if (session.heat_png().empty()) res.status = 404;
        else res.set_content(read_binary(session.heat_png()), "image/png");
    }));
    // Anything else is one of the page's files, by its exact name, or 404.
    server.Get(".*", [&page](const httplib::Request& req, httplib::Response& res) {
        auto it = page.find(req.path);
        if (it == page.end()) {
            res.status = 404;
            return;
        }
        res.set_content(it->second.content, it->second.type.c_str());
    });
}

// Ctrl-C, SIGTERM and SIGHUP stop the server: they are blocked in every thread
// (the server's threads inherit the mask) and one thread waits for them.
class SignalStop {
public:
    explicit SignalStop(httplib::Server& server) {
        sigemptyset(&set_);
        sigaddset(&set_, SIGINT);
        sigaddset(&set_, SIGTERM);
        sigaddset(&set_, SIGHUP);  // the terminal closed
        pthread_sigmask(SIG_BLOCK, &set_, nullptr);
        thread_ = std::thread([this, &server] {
            int signal = 0;
            sigwait(&set_, &signal);
            if (!done_) server.stop();
        });
    }
    // After the server stopped by itself: wakes the waiting thread.
    ~SignalStop() {
        done_ = true;
        pthread_kill(thread_.native_handle(), SIGTERM);
        thread_.join();
    }

private:
    sigset_t set_;
    std::atomic<bool> done_{false};
    std::thread thread_;
};

struct ServeArgs {
    std::vector<std::string> files;
    ServeOptions options;
};

int run_serve(const ServeArgs& a) {
    auto in = classify(a.files);
    if (!in) return fail(in.error(), kToolError);
    if (in->scene.empty() || !in->image.empty())
        return fail(Error("serve needs a scene file (.toml) and the shaders to edit (.vert, .frag: a stage left out, "
                          "or both, is GL's fixed function, generated from the scene)"),
                    kToolError);
    auto scene_text = scene::read_text_file(in->scene, "scene file", scene::kMaxSceneFileBytes);
    if (!scene_text) return fail(scene_text.error(), kResultError);
    std::string page_dir = a.options.page_dir.empty() ? serve_page_dir() : a.options.page_dir;
    if (page_dir.empty()) return fail(Error("the page's files (share/glslrun/serve) are not installed"), kToolError);
    auto page = read_page(page_dir);
    if (!page) return fail(page.error(), kToolError);
    // Before the scratch directory: a Ctrl-C from now on removes it.
    httplib::Server server;
    SignalStop stop(server);
    auto scratch = ScratchDir::create();
    if (!scratch) return fail(scratch.error(), kToolError);
    ServeSession session(*in, std::move(*scene_text), a.options, scratch->path());
    std::mutex mutex;
    server.set_payload_max_length(size_t(scene::kMaxSceneFileBytes));
    // SO_REUSEADDR, so that a restart finds its port free, but not
    // cpp-httplib's default SO_REUSEPORT: with it a second `glslrun serve`
    // shared the port with the first, each getting some of the requests.
    server.set_socket_options([](socket_t sock) {
        int yes = 1;
        setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    add_routes(server, session, mutex, *page);
    // A browser's idle connection holds a worker until this passes, and the stop waits for it.
    server.set_keep_alive_timeout(1);
    int port = a.options.port;
    errno = 0;
    if (port == 0) port = server.bind_to_any_port(a.options.host);
    else if (!server.bind_to_port(a.options.host, port)) port = -1;
    if (port <= 0)
        return fail(Error(fmt::format("cannot listen on {}:{}: {} (--port 0 picks a free port)", a.options.host,
                                      a.options.port, errno ? std::strerror(errno) : "bind failed")),
                    kToolError);
    server.set_pre_routing_handler([port](const httplib::Request& req, httplib::Response& res) {
        if (from_this_page(req, port)) return httplib::Server::HandlerResponse::Unhandled;
        res.status = 403;
        return httplib::Server::HandlerResponse::Handled;
    });
    server.set_post_routing_handler([](const httplib::Request&, httplib::Response& res) {
        res.set_header("Cache-Control", "no-store");
    });
    std::printf("glslrun serve: http://%s:%d/ (Ctrl-C stops)\n", a.options.host.c_str(), port);
    std::fflush(stdout);
    bool ok = server.listen_after_bind();
    std::printf("glslrun serve: stopped\n");
    return ok ? 0 : kToolError;
}

}  // namespace

int serve_main(int argc, char** argv) {
    CLI::App app{"Serves the shader debugger as a web page on 127.0.0.1: the image, the sources and scene to edit, "
                 "a pixel's history and trace, the NaN findings and the error heat map",
                 "glslrun serve"};
    ServeArgs a;
    app.add_option("files", a.files,
                   "shader.vert shader.frag scene.toml (either shader or both may be left out: GL's fixed function; the "
                   "user's files are only read)")
        ->required();
    app.add_option("--port", a.options.port, "the port on 127.0.0.1 (default 8321; 0 picks a free one)")
        ->check(CLI::Range(0, 65535));
    app.add_option("--time-limit", a.options.time_limit,
                   "seconds each render, trace or search may take before it stops with an error (default 10)")
        ->type_name("SECONDS")
        ->check(CLI::Range(1e-3, 1e6));
    app.add_option("--threads", a.options.threads, "worker threads for drawing (default: one per core)")
        ->check(CLI::Range(1, 256));
    add_precision_option(app, a.options.precision);
    app.footer("Prints the page's address and serves until Ctrl-C or SIGTERM. Edits stay in memory: the files are "
               "never written. See debugging.md in the documentation.");
    if (int status = parse_command_line(app, argc, argv); status >= 0) return status;
    return run_serve(a);
}

}  // namespace glslrun::cli
