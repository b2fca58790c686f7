#pragma once
// Every run-time selected model family with the names it accepts, for the
// solver's -help and -listModels (docs/DESIGN.md §5). A new model appears
// here by joining its family's registry; a new family adds one line to
// modelFamilies().

#include <string>
#include <vector>

namespace spoutlab
{

struct ModelFamily
{
    std::string key;   // the couplingProperties entry that selects it, e.g. "dragModel"
    std::string names; // as the errors list them: "Beetstra, DiFelice, Gidaspow"
};

std::vector<ModelFamily> modelFamilies();

} // namespace spoutlab
