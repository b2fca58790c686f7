#include "ModelFamilies.hpp"

#include "DragModel.hpp"
#include "DryingModel.hpp"
#include "HeatTransferModel.hpp"
#include "VoidFractionModel.hpp"

namespace spoutlab
{

namespace
{

template <class Base>
ModelFamily familyOf()
{
    const ModelRegistry<Base>& registry = Base::registry();
    return {registry.key(), registry.namesList()};
}

} // namespace

std::vector<ModelFamily> modelFamilies()
{
    return {familyOf<DragModel>(), familyOf<VoidFractionModel>(), familyOf<HeatTransferModel>(),
            familyOf<DryingModel>()};
}

} // namespace spoutlab
