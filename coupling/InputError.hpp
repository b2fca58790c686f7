#pragma once
// The one exception type for bad user input (dictionary keys, model names).
// Its message is a single line naming where the input came from, so the solver
// can print it as-is and the user knows which entry to fix.

#include <stdexcept>
#include <string>

namespace spoutlab
{

class InputError : public std::runtime_error
{
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

} // namespace spoutlab
