#pragma once
namespace procsim::kinetics
{
const char* fitHelp();
int fitMain(int argc, char** argv);
}
