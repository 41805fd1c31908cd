// writeDiagram (diagram_writer.hpp).
#include "report/diagram_writer.hpp"

#include <ostream>

#include "base/atomic_write.hpp"
#include "base/input_error.hpp"
#include "report/diagram_dot.hpp"
#include "report/graphviz_render.hpp"

namespace shapevo {

void writeDiagram(const pcg::GraphDiagram& diagram, std::string_view format, const std::string& path) {
    const std::string dot = diagramDot(diagram);
    std::string bytes;
    if (format == "dot") bytes = dot;
    else if (format == "svg" || format == "png") bytes = renderWithGraphviz(dot, format);
    else throw InputError(path, "", "unknown graph picture format '" + std::string(format) + "' (expected dot, svg or png)");
    writeStreamAtomically(
        path, [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); }, Replace::Never);
}

}  // namespace shapevo
