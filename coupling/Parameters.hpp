#pragma once
// A named bag of key -> text entries, filled from whatever dictionary the caller
// has (an OpenFOAM sub-dictionary, a YAML node, a test). Models read their
// settings through it so the physics core never depends on OpenFOAM. The
// context ("couplingProperties/GidaspowProps") makes every error point at the
// entry the user has to fix.

#include "InputError.hpp"

#include <map>
#include <string>

namespace spoutlab
{

class Parameters
{
public:
    explicit Parameters(std::string context = "parameters");

    const std::string& context() const { return context_; }

    Parameters& set(const std::string& key, const std::string& value);
    bool has(const std::string& key) const;

    // Throw InputError if the key is missing or its value is not a finite number.
    double getScalar(const std::string& key) const;
    double getScalar(const std::string& key, double defaultValue) const;

    // Like getScalar, but the value must also be a whole number.
    long getInteger(const std::string& key) const;
    long getInteger(const std::string& key, long defaultValue) const;

    std::string getWord(const std::string& key) const;
    std::string getWord(const std::string& key, const std::string& defaultValue) const;

    // Build the InputError for a value that parses but is out of range, in the
    // same one-line format as the errors above.
    InputError badValue(const std::string& key, const std::string& expected) const;

private:
    const std::string& require(const std::string& key, const std::string& expected) const;

    std::string context_;
    std::map<std::string, std::string> entries_;
};

} // namespace spoutlab
