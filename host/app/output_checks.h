#pragma once
// Checks of the files a render will write, made before loading the scene so that a bad path is
// one message after a second instead of after minutes of rendering: the image format is known,
// each target's directory exists and is writable, no target is an existing directory or
// special file, and no two outputs (-o, --stats, --cache-save) name the same file.
#include <string>

#include "app/cli_args.h"

namespace rc {

// The directory a path's file lives in ("." for a bare name, "/" for "/name").
std::string parentDirectory(const std::string& path);
// Throws rc::Error naming the option and the path.
void checkOutputs(const RenderArgs& args, const std::string& imagePath);

}  // namespace rc
