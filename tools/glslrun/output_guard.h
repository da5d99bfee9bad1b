// Outputs are never opened over inputs: `-o tex.png` must not replace the
// scene's own texture, nor `--diff ref.png` the reference. Files are compared
// by device and inode, so a symbolic or hard link to an input is caught as
// well as its own name.
#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "glslrun/scene/scene.h"

namespace glslrun::cli {

class InputFiles {
public:
    // A file that does not exist (yet) is not recorded: nothing can be lost.
    void add(const std::string& path);
    // The scene file, the images and meshes it read, and its passes' shaders.
    void add_scene(const scene::Scene& scene);
    // Refuses a path with a NUL byte, and one that names a recorded input.
    // `what` names the option in the message ("-o", "--diff").
    Status check_output(const std::string& path, const char* what) const;

private:
    struct Id {
        dev_t device;
        ino_t inode;
        std::string path;
    };
    std::vector<Id> inputs_;
};

}  // namespace glslrun::cli
