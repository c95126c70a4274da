#include "app/CliOptions.hpp"

#include "render/StillRenderer.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <regex>

namespace speculum::app {

namespace {

using render::Error;

render::Result<int> parseInt(const std::string& option, const std::string& text, int min, int max) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc::result_out_of_range && end == text.data() + text.size())
        return Error{option + ": " + text + " is out of range (" + std::to_string(min) + ".." +
                     std::to_string(max) + ")"};
    if (ec != std::errc() || end != text.data() + text.size())
        return Error{option + ": expected a whole number, got \"" + text + "\""};
    if (value < min || value > max)
        return Error{option + ": " + text + " is out of range (" + std::to_string(min) + ".." +
                     std::to_string(max) + ")"};
    return value;
}

render::Result<double> parseTime(const std::string& text) {
    try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used != text.size() || !std::isfinite(value))
            throw std::invalid_argument(text);
        if (value < 0.0 || value > 1e7)
            return Error{"--time: " + text + " is out of range (0..1e7 seconds)"};
        return value;
    } catch (const std::exception&) {
        return Error{"--time: expected a number of seconds, got \"" + text + "\""};
    }
}

} // namespace

std::string usageText() {
    return "usage:\n"
           "  speculum [PROJECT]                          open the editor\n"
           "  speculum render PROJECT -o OUT [--size WxH] [--ssaa N] [--time T] [--reference]\n"
           "  speculum explain PROJECT [--size WxH] [--time T] [--frame N] [--json]\n"
           "  speculum bench PROJECT --out DIR [--quick] [--size WxH]\n"
           "  speculum export PROJECT -o OUT.glb|OUT.gltf\n"
           "\n"
           "render writes PNG, JPEG, TIFF or EXR (by the extension of OUT); --size defaults to 1280x720,\n"
           "--ssaa N averages NxN samples per pixel (1..16), --time evaluates animations at T seconds.\n"
           "explain renders a frame and lists the passes that ran and the effects skipped, with reasons;\n"
           "--frame N explains the Nth of N identical frames, showing what a static scene reuses.\n"
           "bench sweeps the settings the scene uses (map type and resolution, parallax, mirror technique "
           "and\n"
           "depth, PCF, tessellation), times each and measures its error against the exact tracer; it "
           "writes\n"
           "results.csv, results.json, plots and report.md into DIR. --quick: fewer points at 480x270.\n"
           "export writes the scene as glTF 2.0: .glb (one file, images inside) or .gltf (with its .bin and\n"
           "images beside it), with the camera and the lights (KHR_lights_punctual).\n";
}

render::Result<CliOptions> parseCommandLine(const std::vector<std::string>& args) {
    CliOptions o;
    std::size_t i = 0;
    if (args.empty())
        return o;
    const std::string& first = args[0];
    if (first == "-h" || first == "--help" || first == "help") {
        o.command = Command::Help;
        return o;
    }
    if (first == "--version") {
        o.command = Command::Version;
        return o;
    }
    if (first == "render")
        o.command = Command::Render;
    else if (first == "explain")
        o.command = Command::Explain;
    else if (first == "bench")
        o.command = Command::Bench;
    else if (first == "export")
        o.command = Command::Export;
    else if (!first.empty() && first[0] == '-')
        return Error{"unknown option " + first + " (see speculum --help)"};
    if (o.command == Command::Editor) {
        if (args.size() > 1)
            return Error{"the editor takes one project file, got " + std::to_string(args.size())};
        o.project = first;
        return o;
    }
    const std::string name = first;
    ++i;

    auto needValue = [&](const std::string& option) -> render::Result<std::string> {
        if (i + 1 >= args.size())
            return Error{option + ": missing value"};
        return args[++i];
    };
    for (; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool renderOrExplain = o.command == Command::Render || o.command == Command::Explain;
        if ((a == "-o" || a == "--output") &&
            (o.command == Command::Render || o.command == Command::Export)) {
            auto v = needValue(a);
            if (!v)
                return Error{v.error()};
            o.output = *v;
        } else if (a == "--out" && o.command == Command::Bench) {
            auto v = needValue(a);
            if (!v)
                return Error{v.error()};
            o.outDir = *v;
        } else if (a == "--size" && (renderOrExplain || o.command == Command::Bench)) {
            auto v = needValue(a);
            if (!v)
                return Error{v.error()};
            static const std::regex size(R"((\d+)[xX](\d+))");
            std::smatch m;
            if (!std::regex_match(*v, m, size))
                return Error{"--size: expected WIDTHxHEIGHT such as 1280x720, got \"" + *v + "\""};
            // No limit per side: stills larger than the GPU's limits render in tiles. Only sizes whose
            // pixels would not fit in memory are refused, here, before any work.
            constexpr int kMaxSide = std::numeric_limits<int>::max();
            auto w = parseInt("--size width", m[1].str(), 1, kMaxSide);
            if (!w)
                return Error{w.error()};
            auto h = parseInt("--size height", m[2].str(), 1, kMaxSide);
            if (!h)
                return Error{h.error()};
            if (render::Status size = render::checkStillSize(*w, *h); !size)
                return Error{"--size: " + size.error()};
            o.width = *w;
            o.height = *h;
            o.sizeGiven = true;
        } else if (a == "--ssaa" && o.command == Command::Render) {
            auto v = needValue(a);
            if (!v)
                return Error{v.error()};
            auto n = parseInt("--ssaa", *v, 1, 16);
            if (!n)
                return Error{n.error()};
            o.ssaa = *n;
        } else if (a == "--time" && renderOrExplain) {
            auto v = needValue(a);
            if (!v)
                return Error{v.error()};
            auto t = parseTime(*v);
            if (!t)
                return Error{t.error()};
            o.time = *t;
        } else if (a == "--reference" && o.command == Command::Render) {
            o.reference = true;
        } else if (a == "--frame" && o.command == Command::Explain) {
            auto v = needValue(a);
            if (!v)
                return Error{v.error()};
            auto n = parseInt("--frame", *v, 1, 100);
            if (!n)
                return Error{n.error()};
            o.frame = *n;
        } else if (a == "--json" && o.command == Command::Explain) {
            o.json = true;
        } else if (a == "--quick" && o.command == Command::Bench) {
            o.quick = true;
        } else if (!a.empty() && a[0] == '-') {
            return Error{name + ": unknown option " + a + " (see speculum --help)"};
        } else if (o.project.empty()) {
            o.project = a;
        } else {
            return Error{name + ": unexpected argument \"" + a + "\""};
        }
    }
    if (o.project.empty())
        return Error{name + ": missing PROJECT file"};
    if (o.command == Command::Render && o.output.empty())
        return Error{"render: missing -o OUT"};
    if (o.command == Command::Export && o.output.empty())
        return Error{"export: missing -o OUT.glb|OUT.gltf"};
    if (o.command == Command::Bench && o.outDir.empty())
        return Error{"bench: missing --out DIR"};
    return o;
}

} // namespace speculum::app
