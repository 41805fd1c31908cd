// renderWithGraphviz (graphviz_render.hpp).
#include "report/graphviz_render.hpp"

#include <mutex>
#include <stdexcept>

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

namespace shapevo {

namespace {

/// Where Graphviz's messages go while a render runs on this thread (agseterrf takes a plain
/// function without user data).
thread_local std::string* graphvizMessages = nullptr;

int collectMessage(char* message) {
    if (graphvizMessages) graphvizMessages->append(message);
    return 0;
}

/// Routes Graphviz's errors and warnings into `messages` while alive; restores the previous handler.
class MessageCapture {
public:
    explicit MessageCapture(std::string& messages) : previous_(agseterrf(collectMessage)), level_(agseterr(AGWARN)) {
        graphvizMessages = &messages;
        agreseterrors();
    }
    ~MessageCapture() {
        graphvizMessages = nullptr;
        agseterr(level_);
        agseterrf(previous_);
    }
    MessageCapture(const MessageCapture&) = delete;
    MessageCapture& operator=(const MessageCapture&) = delete;

private:
    agusererrf previous_;
    agerrlevel_t level_;
};

/// The process's one Graphviz context, made on first use and kept until exit. Graphviz 2.43's
/// pango text-layout plug-in remembers the last font name in a static variable that points into
/// the font table of the context that measured it, so freeing a context and making another one
/// later reads freed memory (AddressSanitizer: heap-use-after-free in pango_textlayout). One
/// context for the process keeps that pointer valid; it is reachable until exit, so it is no
/// leak. Graphviz is not thread-safe: every use holds graphvizMutex.
std::mutex graphvizMutex;
GVC_t* processContext() {
    static GVC_t* const context = gvContext();
    return context;
}

/// One graph and its layout, freed in the order Graphviz needs.
class Render {
public:
    explicit Render(GVC_t* context) : context_(context) {}
    ~Render() {
        if (laidOut_) gvFreeLayout(context_, graph_);
        if (graph_) agclose(graph_);
    }
    Render(const Render&) = delete;
    Render& operator=(const Render&) = delete;

    GVC_t* context_ = nullptr;
    Agraph_t* graph_ = nullptr;
    bool laidOut_ = false;
};

[[noreturn]] void fail(const std::string& what, const std::string& messages) {
    std::string m = "Graphviz could not " + what;
    if (!messages.empty()) m += ": " + messages;
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
    throw std::runtime_error(m);
}

}  // namespace

std::string renderWithGraphviz(const std::string& dot, std::string_view format) {
    const std::lock_guard<std::mutex> lock(graphvizMutex);
    std::string messages;
    const MessageCapture capture(messages);
    Render r(processContext());
    if (!r.context_) fail("start (gvContext)", messages);
    r.graph_ = agmemread(dot.c_str());
    if (!r.graph_) fail("read the graph", messages);
    if (gvLayout(r.context_, r.graph_, "dot") != 0) fail("lay out the graph with dot", messages);
    r.laidOut_ = true;
    char* data = nullptr;
    unsigned int length = 0;
    const std::string formatName(format);
    if (gvRenderData(r.context_, r.graph_, formatName.c_str(), &data, &length) != 0 || !data) {
        if (data) gvFreeRenderData(data);
        fail("render the graph as " + formatName, messages);
    }
    std::string bytes(data, length);
    gvFreeRenderData(data);
    return bytes;
}

}  // namespace shapevo
