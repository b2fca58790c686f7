#include "kinetics/Fit.hpp"
namespace procsim::kinetics
{
const char* fitHelp() { return ""; }
int fitMain(int, char**) { return 1; }
}
