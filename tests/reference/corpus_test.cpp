// The benchmark corpus (bench/corpus/) against Mesa: every program on its
// scene, at a modest 16:9 size, rendered by llvmpipe and by glslrun's two
// backends. The interpreter's and the JIT's images must be byte-identical,
// and both must meet the lecture scenes' rule against Mesa (<= 1/255 per
// channel on >= 99.9% of the covered pixels, Precise).
//
// bench/corpus/mesa-expectations.txt lists the programs known not to meet
// the rule, each with the reason; a listed program must still miss it (an
// unexpected match means the list is stale), and every other must meet it.
// A missing or unreadable corpus file is a failure, never a skip.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const std::string kCorpus = std::string(GLSLRUN_SOURCE_DIR) + "/bench/corpus";
// 16:9 as the benchmark's 1920x1080, small enough for CI's two cores.
constexpr int kWidth = 384, kHeight = 216;

// Every program of the corpus: NAME.vert, NAME.frag and NAME.toml.
std::vector<std::string> corpus_programs() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(kCorpus))
        if (entry.path().extension() == ".frag") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// "name  # reason" per line; '#' lines and blank lines are comments.
std::map<std::string, std::string> expected_mismatches() {
    std::map<std::string, std::string> expected;
    std::ifstream in(kCorpus + "/mesa-expectations.txt");
    REQUIRE(in);
    std::string line;
    while (std::getline(in, line)) {
        size_t hash = line.find('#');
        std::string name = line.substr(0, hash);
        name.erase(name.find_last_not_of(" \t") + 1);
        if (name.empty()) continue;
        INFO("mesa-expectations.txt: " << line);
        REQUIRE(hash != std::string::npos);  // every entry gives its reason
        REQUIRE(expected.emplace(name, line.substr(hash + 1)).second);
    }
    return expected;
}

Result<scene::Image> render(const reference::Inputs& in, Backend backend) {
    auto program = Program::compile(in.vertex, in.fragment);
    if (!program) return program.error();
    program->exec.backend = backend;
    program->exec.precision = Precision::Precise;
    Framebuffer fb(in.scene.width, in.scene.height, false, scene::color_buffers(in.scene));
    auto stats = scene::render_scene(*program, in.scene, fb);
    if (!stats) return stats.error();
    return scene::read_framebuffer(fb, 0);
}

}  // namespace

TEST_CASE("Every corpus program matches Mesa, or is listed with its reason", "[reference][corpus]") {
    auto programs = corpus_programs();
    auto expected = expected_mismatches();
    CHECK(programs.size() >= 15);
    for (const auto& [name, reason] : expected) {
        INFO("mesa-expectations.txt lists " << name);
        CHECK(std::find(programs.begin(), programs.end(), name) != programs.end());
    }
    for (const std::string& name : programs) {
        INFO("corpus program " << name);
        auto vs = reference::read_shader(kCorpus + "/" + name + ".vert");
        auto fs = reference::read_shader(kCorpus + "/" + name + ".frag");
        auto sc = scene::load_scene(kCorpus + "/" + name + ".toml");
        if (!vs || !fs || !sc) {
            FAIL_CHECK((!vs ? vs.error().str() : !fs ? fs.error().str() : sc.error().str()));
            continue;
        }
        REQUIRE(scene::resize_scene(*sc, kWidth, kHeight));
        reference::Inputs in{{*vs}, {*fs}, std::move(*sc)};
        auto mesa = glref::render_with_mesa(reference::kDriver, in.vertex, in.fragment, in.scene);
        auto interp = render(in, Backend::Interp);
        if (!mesa || !interp) {
            FAIL_CHECK((!mesa ? "Mesa: " + mesa.error().str() : "glslrun: " + interp.error().str()));
            continue;
        }
        if (jit_available()) {
            auto jit = render(in, Backend::Jit);
            REQUIRE(jit);
            CHECK(jit->rgba == interp->rgba);  // the backends agree bit for bit
        }
        scene::CompareOptions options;
        options.tolerance = reference::kTolerance;
        options.min_fraction_within = reference::kMinFractionWithin;
        options.clear_color = scene::to_rgba8(in.scene.clear_color);
        auto stats = scene::compare_images(mesa->image, *interp, options);
        REQUIRE(stats);
        auto listed = expected.find(name);
        std::printf("corpus %-14s %s%s\n", name.c_str(), stats->summary().c_str(),
                    listed == expected.end() ? "" : " (listed: expected to differ)");
        INFO(stats->summary());
        CHECK(stats->covered >= stats->pixels / 100);  // a blank pair would pass vacuously
        bool keep = std::getenv("GLSLRUN_SAVE_REFERENCE_IMAGES") != nullptr;
        if (listed == expected.end()) {
            // INFO lasts for its scope: the message is built here, outside any if.
            std::string saved = stats->passed && !keep ? std::string()
                                                       : reference::save_failure("corpus-" + name, mesa->image, *interp);
            INFO("images:" << saved);
            CHECK(stats->passed);
        } else {
            if (keep) reference::save_failure("corpus-" + name, mesa->image, *interp);
            INFO("listed in bench/corpus/mesa-expectations.txt (" << listed->second
                 << ") but now matches Mesa: remove it from the list");
            CHECK(!stats->passed);
        }
    }
}
