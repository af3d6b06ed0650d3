#include "catchsession.h"

int main(int argc, char* argv[])
{
    return runCatchSession(argc, argv);
}
