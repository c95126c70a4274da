#include "app/CliOptions.hpp"

#include "render/SceneLimits.hpp"
#include "render/StillRenderer.hpp"
#include "render/io/Printable.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <regex>
#include <string_view>
#include <system_error>

namespace speculum::app {

namespace {

using render::Error;

render::Result<int> parseInt(const std::string& option, const std::string& text, int min, int max) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc::result_out_of_range && end == text.data() + text.size())
        return Error{option + ": " + render::quoted(text) + " is out of range (" + std::to_string(min) +
                     ".." + std::to_string(max) + ")"};
    if (ec != std::errc() || end != text.data() + text.size())
        return Error{option + ": expected a whole number, got " + render::quoted(text)};
    if (value < min || value > max)
        return Error{option + ": " + render::quoted(text) + " is out of range (" + std::to_string(min) +
                     ".." + std::to_string(max) + ")"};
    return value;
}

render::Result<double> parseTime(const std::string& text) {
    try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used != text.size() || !std::isfinite(value))
            throw std::invalid_argument(text);
        if (value < 0.0 || value > 1e7)
            return Error{"--time: " + render::quoted(text) + " is out of range (0..1e7 seconds)"};
        return value;
    } catch (const std::exception&) {
        return Error{"--time: expected a number of seconds, got " + render::quoted(text)};
    }
}

constexpr std::array<std::string_view, 6> kCommands = {"render", "explain", "bench",
                                                       "time",   "export",  "help"};

// Edit distance (insertions, deletions, substitutions, case ignored), for "did you mean".
std::size_t distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// The first word opens the editor when it names a project: anything that exists on disk, or that is
// written as a path (a slash or a dot: "scene.speculum.json", "./new"), alone. A bare word that names
// nothing ("rendr"), or a non-path followed by more arguments, is a mistyped command instead: refused here,
// before Qt starts, rather than opening an editor on a file that does not exist.
bool looksLikeCommand(const std::string& first, std::size_t argumentCount) {
    std::error_code ec;
    if (first.empty() ||
        std::filesystem::symlink_status(first, ec).type() != std::filesystem::file_type::not_found)
        return false;
    const bool pathLike = first.find_first_of("/.") != std::string::npos;
    return !pathLike || argumentCount > 1;
}

std::string unknownCommand(const std::string& word) {
    std::string_view best;
    std::size_t bestDistance = 3; // suggest only within two edits
    for (std::string_view command : kCommands) {
        const std::size_t d =
            distance(word.size() > 64 ? std::string_view(word).substr(0, 64) : word, command);
        if (d < bestDistance) {
            best = command;
            bestDistance = d;
        }
    }
    std::string message = "unknown command " + render::quoted(word);
    if (!best.empty())
        return message + " (did you mean '" + std::string(best) + "'?)";
    return message + " (commands: render, explain, bench, time, export; see speculum --help)";
}

} // namespace

std::string usageText() {
    return "usage:\n"
           "  speculum [PROJECT]                          open the editor\n"
           "  speculum render PROJECT -o OUT [--size WxH] [--ssaa N] [--time T] [--reference] "
           "[--keep-going]\n"
           "  speculum explain PROJECT [--size WxH] [--time T] [--frame N] [--json]\n"
           "  speculum bench PROJECT --out DIR [--quick] [--size WxH] [--keep-going]\n"
           "  speculum time PROJECT [--size WxH] [--frames N] [--animated] [--time T] [--half-float] "
           "[--json]\n"
           "  speculum export PROJECT -o OUT.glb|OUT.gltf [--keep-going]\n"
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
           "time draws N frames (default 100, after 5 warm-up frames) into an 8-bit target like a window's\n"
           "and prints the median, minimum and maximum wall-clock frame time, each frame timed until its\n"
           "pixels can be read, and each pass kind's share; a static scene reuses its shadow and\n"
           "environment maps as the editor does, --animated plays the animation at 60 frames a second.\n"
           "--half-float draws every frame through the half-float buffer and its composite, to compare.\n"
           "export writes the scene as glTF 2.0: .glb (one file, images inside) or .gltf (with its .bin and\n"
           "images beside it), with the camera and the lights (KHR_lights_punctual).\n"
           "A model or texture the scene names that is missing or unreadable is an error for render, bench\n"
           "and export; --keep-going goes on without it (a warning). Everything a frame drops (lights "
           "beyond\n"
           "8, a mirror it cannot reflect) is a warning on stderr. An output that is an input (the project,\n"
           "a model, a texture) is refused. Exit status: 0 done, 1 failed, 2 bad command line.\n";
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
    else if (first == "time")
        o.command = Command::Time;
    else if (!first.empty() && first[0] == '-')
        return Error{"unknown option " + render::quoted(first) + " (see speculum --help)"};
    if (o.command == Command::Editor) {
        if (looksLikeCommand(first, args.size()))
            return Error{unknownCommand(first)};
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
        const bool timed = o.command == Command::Time;
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
        } else if (a == "--size" && (renderOrExplain || timed || o.command == Command::Bench)) {
            auto v = needValue(a);
            if (!v)
                return Error{v.error()};
            static const std::regex size(R"((\d+)[xX](\d+))");
            std::smatch m;
            if (!std::regex_match(*v, m, size))
                return Error{"--size: expected WIDTHxHEIGHT such as 1280x720, got " + render::quoted(*v)};
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
            auto n = parseInt("--ssaa", *v, render::kMinSsaa, render::kMaxSsaa);
            if (!n)
                return Error{n.error()};
            o.ssaa = *n;
        } else if (a == "--time" && (renderOrExplain || timed)) {
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
        } else if (a == "--json" && (o.command == Command::Explain || timed)) {
            o.json = true;
        } else if (a == "--frames" && timed) {
            auto v = needValue(a);
            if (!v)
                return Error{v.error()};
            auto n = parseInt("--frames", *v, 1, 100000);
            if (!n)
                return Error{n.error()};
            o.frames = *n;
        } else if (a == "--animated" && timed) {
            o.animated = true;
        } else if (a == "--half-float" && timed) {
            o.halfFloat = true;
        } else if (a == "--keep-going" && o.command != Command::Explain) {
            o.keepGoing = true;
        } else if (a == "--quick" && o.command == Command::Bench) {
            o.quick = true;
        } else if (!a.empty() && a[0] == '-') {
            return Error{name + ": unknown option " + render::quoted(a) + " (see speculum --help)"};
        } else if (o.project.empty()) {
            o.project = a;
        } else {
            return Error{name + ": unexpected argument " + render::quoted(a)};
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
