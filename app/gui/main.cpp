// GG Studio: the GEMMA-GRAFCET editor. Usage: ggstudio [MODEL]

#include "editor/app/application.h"

int main(int argc, char* argv[])
{
    // The startup lives in the editor library, where the benchmarks run it too.
    return editor::runApplication(argc, argv);
}
