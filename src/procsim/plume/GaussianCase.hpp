#pragma once
namespace procsim::plume
{
int gaussianMain(int argc, char** argv);
}
