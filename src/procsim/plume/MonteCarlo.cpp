#include "plume/MonteCarlo.hpp"
int procsim::plume::monteCarloMain(int, char**) { return 0; }
