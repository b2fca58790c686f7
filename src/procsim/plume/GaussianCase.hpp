#pragma once
// The `procsim plume gaussian` case, and the model settings it shares with
// `procsim plume montecarlo`.
#include <string>
#include <vector>

#include "common/YamlInput.hpp"
#include "plume/Gaussian.hpp"

namespace procsim::plume
{

struct GaussianSetup
{
    GaussianOptions options;
    std::vector<Source> sources;
    std::vector<Receptor> receptors;
    double standardUgM3 = 120;
};

// Keys read by parseGaussianSetup (for rejectUnknown of the callers).
const std::vector<std::string>& gaussianSetupKeys();
GaussianSetup parseGaussianSetup(const YamlInput& in);

} // namespace procsim::plume
