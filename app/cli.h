// The command line (CLI11): run, capture, check, bench frame. Returns the process exit
// code: 0 ok, 1 runtime failure, 2 bad input.
#pragma once

namespace vista {

int runCli(int argc, char** argv);

}  // namespace vista
