#pragma once
// The coarse-graining factor cg of a run (the couplingProperties key
// "coarseGraining", default 1; Particle.hpp, docs/DESIGN.md), and the
// combinations the solver refuses, each with one line naming the file and
// the key. LIGGGHTS 3.8 scales nothing itself (it has no command that sets
// its own factor, and its hooke/stiffness model refuses one), so the input
// scales its particles by the LIGGGHTS variable cg the solver passes it.

#include <string>

namespace spoutlab
{

// cg as read (NaN when the entry is not a single number), written as the
// file spells it: cg, or an InputError unless it is finite and >= 1.
double checkedCoarseGraining(double cg, const std::string& written, const std::string& file);

// cg != 1 with a LIGGGHTS input that never refers to ${cg} (its parcels would
// keep the original diameter, stiffness and damping): an InputError.
void checkCoarseGrainedInput(double cg, bool inputUsesCg, const std::string& file, const std::string& input);

// liggghtsVariables may not set cg itself: the solver passes it from
// coarseGraining, and two values could disagree.
void checkNoOwnCg(bool liggghtsVariablesSetCg, const std::string& file);

} // namespace spoutlab
