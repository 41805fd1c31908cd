// targetFromGenome: what `shapevo target G.genome --image CONFIG -o OUT.png` does — the model of a
// genome of the config's grammar (a run's best.genome, or one `sample --genome` wrote) drawn
// through the config's frame as a picture target it reaches exactly (LoadedTarget::
// drawModelTarget: black where it covers a pixel, white elsewhere). A reachable target: a search
// from other seeds can be checked against a picture whose optimum is known.
#pragma once
#include <iosfwd>

#include "run/target_from_mesh.hpp"

namespace shapevo {

/// @throw InputError without --image, for an output that is not a new .png, a genome of another
/// grammar, or a config whose target cannot be loaded.
void makeTargetFromGenome(const TargetRequest& request, std::ostream& out);

}  // namespace shapevo
