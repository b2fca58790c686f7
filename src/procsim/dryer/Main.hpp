#pragma once

namespace procsim::dryer
{

// `procsim dryer <command> ...`; argv[0] == "dryer".
int main(int argc, char** argv);

} // namespace procsim::dryer
