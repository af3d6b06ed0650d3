#include "commands.h"

#include <iostream>

int main(int argc, char** argv)
{
    std::vector<std::string> words(argv + 1, argv + argc);
    return cli::run(words, {std::cout, std::cerr});
}
