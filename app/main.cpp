// vista: outdoor terrain renderer. See README.md and `vista --help`.
#include "app/cli.h"

int main(int argc, char** argv) { return vista::runCli(argc, argv); }
