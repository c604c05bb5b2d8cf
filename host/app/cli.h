#pragma once
// Dispatches `rcache SCENE.xml ...`, `rcache devices`, `rcache verify`, `rcache diff`.
// Returns the process exit code; never throws (every rc::Error becomes one line on stderr).
namespace rc {
int runCli(int argc, char** argv);
}
