// The table of commands (commands.hpp).
#include "cli/commands.hpp"

#include <array>

namespace shapevo {

namespace {

constexpr std::array<CommandEntry, 11> kCommands{{
    {"run", "Evolve a model: shapevo run CONFIG.toml", true, RunCommand::addOptions, RunCommand::run},
    {"sample",
     "Write random derivations of a grammar (no evolution): every sibling position of a slot is expressed with the slot's "
     "prob, independently, recursively; a 2D graph grammar (.yml) is derived and drawn as SVG or PNG",
     false, SampleCommand::addOptions, SampleCommand::run},
    {"target",
     "Make a target from a mesh (OBJ, PLY, STL, OFF, glTF/GLB, FBX, 3MF, DAE, 3DS or any other format Assimp reads): a volume "
     "(OpenVDB level set of its inside; seams, small holes and non-manifold edges are repaired and reported) or, with --image, "
     "a picture of its silhouette or shadow",
     false, TargetCommand::addOptions, TargetCommand::run},
    {"translate",
     "Print what a grammar file of another front end (a CastleMaker rule file .rule, a procedural content graph .pcg) compiles into, in the shapevo grammar "
     "language: shapevo translate FILE",
     false, TranslateCommand::addOptions, TranslateCommand::run},
    {"evaluate",
     "Score a saved chromosome against a config's target (volume or image), as run scores it: shapevo evaluate CONFIG.toml "
     "FILE.genome",
     false, EvaluateCommand::addOptions, EvaluateCommand::run},
    {"resume", "Continue a run from its newest complete checkpoint: shapevo resume RUN_DIR", true, ResumeCommand::addOptions,
     ResumeCommand::run},
    {"inspect", "Summarise a checkpoint: shapevo inspect RUN_DIR|CHECKPOINT|ISLAND.h5", false, InspectCommand::addOptions,
     InspectCommand::run},
    {"export", "Write the best model of a checkpoint: shapevo export RUN_DIR|CHECKPOINT|ISLAND.h5 --best -o FILE", false,
     ExportCommand::addOptions, ExportCommand::run},
    {"render",
     "Draw a shaded picture of a model (PNG; on the CPU, no display needed): shapevo render MODEL|RUN_DIR|CHECKPOINT -o "
     "view.png",
     false, RenderCommand::addOptions, RenderCommand::run},
    {"graph",
     "Draw a grammar's generator graph (rules as nodes, child slots and inline calls as edges, cyclic edges dashed, "
     "topological numbers, loop nodes starred, as in the PCGR paper) with Graphviz's library: shapevo graph FILE.grammar -o "
     "graph.svg",
     false, GraphCommand::addOptions, GraphCommand::run},
    {"reference",
     "Print the reference written from the code: every config key (config), every command's --help (commands) or the man "
     "page (man): shapevo reference config",
     false, ReferenceCommand::addOptions, ReferenceCommand::run},
}};

}  // namespace

std::span<const CommandEntry> commands() { return kCommands; }

std::string manyRankCommandNames() {
    std::string out;
    std::size_t n = 0;
    for (const CommandEntry& c : kCommands) n += c.manyRanks;
    for (const CommandEntry& c : kCommands) {
        if (!c.manyRanks) continue;
        if (!out.empty()) out += --n == 1 ? " and " : ", ";
        out += "'" + std::string(c.name) + "'";
    }
    return out;
}

}  // namespace shapevo
