#include "plume/GaussianCase.hpp"
int procsim::plume::gaussianMain(int, char**) { return 0; }
