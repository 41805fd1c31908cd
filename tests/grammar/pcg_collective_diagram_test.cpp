// `shapevo graph` draws the collective nodes' ports square: in the diagram of grammars/pcg/house.pcg
// (PCGR Fig. 9) exactly the ports of `area` (order_by) and `one` (amount_filter) are collective,
// every other port single.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "grammar/pcg/pcg_front_end.hpp"

namespace shapevo {

TEST(PcgCollectiveDiagram, OnlyTheCollectiveNodesPortsAreDrawnCollective) {
    const std::string path = test::sourcePath("grammars/pcg/house.pcg");
    const pcg::GraphDiagram d = pcg::pcgDiagram(test::readFile(path), path);
    std::size_t collective = 0;
    for (const pcg::DiagramNode& n : d.nodes)
        for (const pcg::DiagramPort& p : n.ports) {
            const bool listNode = n.name == "area" || n.name == "one";
            EXPECT_EQ(p.kind == pcg::PortKind::Collective, listNode) << n.name << "." << p.name;
            collective += p.kind == pcg::PortKind::Collective;
        }
    EXPECT_EQ(collective, 5u);  // area: in, out; one: in, first, rest
}

}  // namespace shapevo
