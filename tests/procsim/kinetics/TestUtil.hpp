#pragma once
// Helpers for the kinetics tests: write small YAML files into a scratch directory.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace kt
{

inline std::string scratchDir()
{
    const auto d =
        std::filesystem::temp_directory_path() / ("procsim_kinetics_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d.string();
}

inline std::string writeFile(const std::string& name, const std::string& text)
{
    const std::string path = scratchDir() + "/" + name;
    std::ofstream(path) << text;
    return path;
}

inline std::string casesDir()
{
    return KINETICS_CASES_DIR;
}

} // namespace kt
