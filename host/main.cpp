// rcache command-line entry point; everything lives in host/app.
#include "app/cli.h"

int main(int argc, char** argv) { return rc::runCli(argc, argv); }
