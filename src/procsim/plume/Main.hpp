#pragma once
// procsim plume: entry point called by procsim's main (argv[0] = "plume").
namespace procsim::plume
{
int main(int argc, char** argv);
}
