#pragma once
namespace procsim::plume
{
int monteCarloMain(int argc, char** argv);
}
