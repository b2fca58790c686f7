#include "CellLocator.hpp"

namespace spoutlab {

CellLocator::~CellLocator() = default;

}  // namespace spoutlab
