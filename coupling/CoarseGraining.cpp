#include "CoarseGraining.hpp"

#include "InputError.hpp"

#include <cmath>

namespace spoutlab
{

double checkedCoarseGraining(double cg, const std::string& written, const std::string& file)
{
    if (std::isfinite(cg) && cg >= 1.0) return cg;
    throw InputError(file
                     + ": key 'coarseGraining' expected a factor >= 1 (parcel diameter / original particle "
                       "diameter), got '"
                     + written + "'");
}

void checkCoarseGrainedInput(double cg, bool inputUsesCg, const std::string& file, const std::string& input)
{
    if (cg == 1.0 || inputUsesCg) return;
    throw InputError(
        file + ": key 'coarseGraining' is not 1, but LIGGGHTS input '" + input
        + "' never uses ${cg}: expected it to scale its particles by it (liggghts_inputs/README.md)");
}

void checkNoOwnCg(bool liggghtsVariablesSetCg, const std::string& file)
{
    if (!liggghtsVariablesSetCg) return;
    throw InputError(file
                     + ": key 'liggghtsVariables/cg' expected nothing (spoutFoam passes LIGGGHTS cg from "
                       "'coarseGraining')");
}

} // namespace spoutlab
