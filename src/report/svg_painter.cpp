// SvgPainter: each call appends one element to the document text.
#include "report/svg_painter.hpp"

#include <cstdio>

namespace shapevo {

namespace {
std::string num(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.2f", v);
    return s;
}
std::string colour(PlotColour c) {
    char s[16];
    std::snprintf(s, sizeof s, "#%02x%02x%02x", c.r & 255, c.g & 255, c.b & 255);
    return s;
}
std::string opacity(const char* attribute, PlotColour c) {
    return c.opacity < 1 ? std::string(" ") + attribute + "=\"" + num(c.opacity) + "\"" : std::string();
}
std::string pointList(const PlotPainter::Points& points) {
    std::string out;
    for (const auto& [x, y] : points) out += num(x) + "," + num(y) + " ";
    if (!out.empty()) out.pop_back();
    return out;
}
std::string classOf(const std::string& name) { return name.empty() ? "" : " class=\"" + xmlEscape(name) + "\""; }
}  // namespace

std::string xmlEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

SvgPainter::SvgPainter(int width, int height, const std::string& title) {
    const std::string w = std::to_string(width), h = std::to_string(height);
    body_ = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w +
            "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\" font-family=\"sans-serif\">\n<title>" +
            xmlEscape(title) + "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

void SvgPainter::polyline(const Points& points, PlotColour c, double width, bool dashed, const std::string& name) {
    if (points.empty()) return;
    body_ += "<polyline" + classOf(name) + " fill=\"none\" stroke=\"" + colour(c) + "\"" + opacity("stroke-opacity", c) +
             " stroke-width=\"" + num(width) + "\"" + (dashed ? " stroke-dasharray=\"6 3\"" : "") +
             " stroke-linejoin=\"round\" points=\"" + pointList(points) + "\"/>\n";
}

void SvgPainter::polygon(const Points& points, PlotColour fill, const std::string& name) {
    if (points.empty()) return;
    body_ += "<polygon" + classOf(name) + " fill=\"" + colour(fill) + "\"" + opacity("fill-opacity", fill) +
             " stroke=\"none\" points=\"" + pointList(points) + "\"/>\n";
}

void SvgPainter::rect(double x, double y, double w, double h, PlotColour fill) {
    body_ += "<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(w) + "\" height=\"" + num(h) + "\" fill=\"" +
             colour(fill) + "\"" + opacity("fill-opacity", fill) + "/>\n";
}

void SvgPainter::circle(double x, double y, double radius, PlotColour fill) {
    body_ += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"" + num(radius) + "\" fill=\"" + colour(fill) + "\"" +
             opacity("fill-opacity", fill) + "/>\n";
}

void SvgPainter::text(double x, double y, const std::string& text, const PlotText& style) {
    static const char* const kAnchor[] = {"start", "middle", "end"};
    body_ += "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" font-size=\"" + num(style.size) + "\" text-anchor=\"" +
             kAnchor[int(style.anchor)] + "\"" + (style.bold ? " font-weight=\"bold\"" : "") +
             (style.colour.r || style.colour.g || style.colour.b ? " fill=\"" + colour(style.colour) + "\"" : "") +
             (style.vertical ? " transform=\"rotate(-90 " + num(x) + " " + num(y) + ")\"" : "") + ">" + xmlEscape(text) +
             "</text>\n";
}

double SvgPainter::textWidth(const std::string& text, double size, bool bold) { return measure_.textWidth(text, size, bold); }

}  // namespace shapevo
