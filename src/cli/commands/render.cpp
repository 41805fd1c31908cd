// `shapevo render MODEL|RUN_DIR|CHECKPOINT -o view.png`: a shaded picture of a mesh file or of a
// checkpoint's best model (report/render/model_picture.hpp).
#include <array>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "checkpoint/checkpoint_path.hpp"
#include "cli/commands.hpp"
#include "geometry/derive.hpp"
#include "mesh/mesh_reader.hpp"
#include "report/model_writer.hpp"
#include "report/render/model_picture.hpp"
#include "run/command_options.hpp"
#include "run/model_export.hpp"

namespace shapevo {

namespace {

struct RenderOptions {
    std::string path;
    std::string out;
    std::string view = "three-quarter";
    std::string size = "800x600";
};
RenderOptions renderOptions;

}  // namespace

void RenderCommand::addOptions(CLI::App& command) {
    RenderOptions& o = renderOptions;
    command.add_option("path", o.path,
                       "a mesh file (.obj, .ply, .stl; drawn in a neutral colour), or a run folder, checkpoint folder, or a "
                       "checkpoint's run.h5 or island-NNNN.h5 (the checkpoint's best model over all islands, in its colours)")
        ->required();
    command.add_option("-o,--output", o.out, "PNG file to write; must not exist")->required();
    command.add_option("--view", o.view, "three-quarter (from the front right, 30 degrees up), front, side, top, or three "
                                         "(front, side and top side by side)")
        ->capture_default_str();
    command.add_option("--size", o.size, "the size of each view, WIDTHxHEIGHT in pixels (16 to 8192 each)")->capture_default_str();
}

void RenderCommand::run(const CommandContext&) {
    const RenderOptions& o = renderOptions;
    requireOutputFormat(o.out, std::array<std::string_view, 1>{"png"}, "-o");
    refuseExisting(o.out);
    const std::vector<View> views = parseViews(o.view);
    const PictureSize size = parsePictureSize(o.size);
    if (std::filesystem::is_directory(o.path) || formatOfPath(o.path) == "h5") {
        const CheckpointBest b = bestOfCheckpoint(resolveCheckpointPath(o.path));
        const std::string drew = b.model->render(b.best, views, o.view, size, o.out);
        std::cout << "wrote " << o.out << " (" << drew << "; best model: " << b.from << ")\n";
        return;
    }
    const Mesh mesh = readMesh(o.path);
    const std::string what = o.path;
    writeModelPicture(mesh, views, size, o.out);
    std::cout << "wrote " << o.out << " (" << size.width * int(views.size()) << "x" << size.height << ", " << o.view << " view"
              << (views.size() > 1 ? "s" : "") << " of " << mesh.triangles.size() << " triangles; " << what << ")\n";
}

}  // namespace shapevo
