#pragma once

#include "asr_ism/demonstration.hpp"
#include "asr_ism/ism_recognizer.hpp"
#include "asr_ism_tree/ism_tree.hpp"
#include "asr_ism_tree/relation_topology.hpp"

namespace asr_ism_tree {

/// Learns an ISM tree for the demonstrated scene from a connected relation topology over the
/// demonstration's objects (the paper's Algo. 1). The topology is partitioned into stars; each
/// star becomes one ISM whose reference is the star's centre. A star's ISM replaces its centre
/// in the neighbourhood of its parent star (the closest to the root that has it), as a placeholder
/// member whose trajectory is that centre's, so the tree is as low as the topology allows. Stars
/// are converted deepest first, in reverse extraction order within a level, and named
/// `<scene>_sub<k>` with k counting down to 0; the root ISM is named `<scene>`.
/// Throws InputError if the topology is disconnected or its objects differ from the
/// demonstration's.
IsmTree generateIsmTree(const asr_ism::Demonstration& demonstration,
                        const RelationTopology& topology,
                        const asr_ism::IsmRecognitionParameters& parameters, int root_center = -1);

}  // namespace asr_ism_tree
