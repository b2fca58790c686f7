#include "plume/Main.hpp"
int procsim::plume::main(int, char**) { return 0; }
