#pragma once

namespace procsim::kinetics
{

// procsim kinetics <run|sensitivity|fit|corona> ...   (argv[0] = "kinetics")
int main(int argc, char** argv);

} // namespace procsim::kinetics
