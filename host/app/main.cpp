// main.cpp — `wavefront`: the command line (cli/run_command.h), with the
// version text that only the program is built with (cli/version_text.h).
#include "cli/run_command.h"
#include "cli/version_text.h"

int main(int argc, const char** argv) { return wf::run_command_line(argc, argv, wf::version_text); }
