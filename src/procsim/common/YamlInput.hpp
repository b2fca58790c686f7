#pragma once
// Typed access to a YAML input file with one-line errors that name the file,
// the key path and what was expected.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "common/Cli.hpp"

namespace procsim
{

// A file named in an input, taken relative to the directory dir of that
// input unless it is absolute.
std::string relativeTo(const std::string& dir, const std::string& path);

class YamlInput
{
public:
    // Load a file ("file.yaml: cannot be read" / "file.yaml: line 3: <yaml error>").
    static YamlInput load(const std::string& path);

    YamlInput(YAML::Node node, std::string file, std::string path);

    const std::string& file() const { return file_; }
    const std::string& path() const { return path_; } // e.g. "reactor.volume"
    const YAML::Node& node() const { return node_; }

    bool has(const std::string& key) const;
    YamlInput child(const std::string& key) const; // required map/sequence
    std::vector<YamlInput> items() const;          // elements of a sequence
    std::vector<std::string> keys() const;         // keys of a map

    double number(const std::string& key, const std::string& unit = "") const;
    double number(const std::string& key, double fallback, const std::string& unit = "") const;
    double positive(const std::string& key, const std::string& unit = "") const;
    double nonNegative(const std::string& key, const std::string& unit = "") const;
    // Numbers are finite and whole: ".inf", ".nan", "1e400" and "3abc" are refused.
    double within(const std::string& key, double lo, double hi, const std::string& unit = "") const;
    double within(const std::string& key, double fallback, double lo, double hi,
                  const std::string& unit = "") const;
    long integer(const std::string& key) const; // within the range of int
    long integer(const std::string& key, long min, long max) const;
    std::string text(const std::string& key) const;
    std::string text(const std::string& key, const std::string& fallback) const;
    std::vector<double> numbers(const std::string& key, const std::string& unit = "") const;
    // A non-empty list of numbers, each above the one before it (a grid, a
    // series of times): an empty list, a value given twice or out of order is refused.
    std::vector<double> increasingNumbers(const std::string& key, const std::string& unit = "") const;

    // "file: key 'path.key' expected <what>, got '<value>'"
    InputError error(const std::string& key, const std::string& expected) const;

    // Keys present in the map but not in `known` -> error naming the first one.
    void rejectUnknown(const std::vector<std::string>& known) const;

private:
    YAML::Node node_;
    std::string file_;
    std::string path_;

    std::string keyPath(const std::string& key) const;
    YAML::Node required(const std::string& key, const std::string& expected) const;
};

} // namespace procsim
