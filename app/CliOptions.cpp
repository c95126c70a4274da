#include "app/CliOptions.hpp"

#include "base/Printable.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/reference/Tracer.hpp"
#include "render/renderer/StillRenderer.hpp"

#include <CLI/CLI.hpp>
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

using base::Error;

base::Result<int> parseInt(const std::string& option, const std::string& text, int min, int max) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc::result_out_of_range && end == text.data() + text.size())
        return Error{option + ": " + base::quoted(text) + " is out of range (" + std::to_string(min) + ".." +
                     std::to_string(max) + ")"};
    if (ec != std::errc() || end != text.data() + text.size())
        return Error{option + ": expected a whole number, got " + base::quoted(text)};
    if (value < min || value > max)
        return Error{option + ": " + base::quoted(text) + " is out of range (" + std::to_string(min) + ".." +
                     std::to_string(max) + ")"};
    return value;
}

// Plain decimal notation, as --ssaa and --size read their whole numbers: no spaces around it, no
// hexadecimal floats ("0x1p1" is no way to write two seconds), no infinities.
base::Result<double> parseTime(const std::string& text) {
    double value = 0.0;
    const auto [end, ec] =
        std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return Error{"--time: expected a number of seconds, got " + base::quoted(text)};
    if (value < 0.0 || value > 1e7)
        return Error{"--time: " + base::quoted(text) + " is out of range (0..1e7 seconds)"};
    return value;
}

// explain --preview SCALE[,CUT]: the fraction of the width and height drawn, and the levels of mirror
// nesting left out.
base::Status parsePreview(const std::string& text, render::PreviewPolicy& preview) {
    const std::string expected =
        "--preview: expected SCALE[,CUT] such as 0.5 or 0.25,1, got " + base::quoted(text);
    const std::size_t comma = text.find(',');
    const std::string scaleText = text.substr(0, comma);
    double scale = 0.0;
    try {
        std::size_t used = 0;
        scale = std::stod(scaleText, &used);
        if (used != scaleText.size() || !std::isfinite(scale))
            return Error{expected};
    } catch (const std::exception&) {
        return Error{expected};
    }
    if (scale < render::kMinResolutionScale || scale > 1.0)
        return Error{"--preview: scale " + base::quoted(scaleText) + " is out of range (0.125..1)"};
    preview.scale = scale;
    if (comma == std::string::npos)
        return base::Done{};
    auto cut = parseInt("--preview mirror depth cut", text.substr(comma + 1), 0, render::kMaxMirrorDepth);
    if (!cut)
        return Error{cut.error()};
    preview.mirrorDepthCut = *cut;
    return base::Done{};
}

constexpr std::array<std::string_view, 7> kCommands = {"render", "explain", "bench", "time",
                                                       "export", "join",    "help"};

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
    std::string message = "unknown command " + base::quoted(word);
    if (!best.empty())
        return message + " (did you mean '" + std::string(best) + "'?)";
    return message + " (commands: render, explain, bench, time, export, join; see speculum --help)";
}

} // namespace

std::string usageText() {
    return "usage:\n"
           "  speculum [PROJECT]                          open the editor\n"
           "  speculum --recover FILE                     open the editor on an editor's recovery file\n"
           "  speculum render PROJECT -o OUT [--size WxH] [--ssaa N] [--time T] [--reference [--samples N]] "
           "[--screen-space-sources] [--keep-going]\n"
           "  speculum render PROJECT --frames A..B|--turntable SECONDS -o OUT [--fps N] [--shard K/N "
           "[--contiguous]] [still options]\n"
           "  speculum join SEQUENCE -o CLIP [--frames A..B] [--fps N]\n"
           "  speculum explain PROJECT [--size WxH] [--time T] [--frame N [--animated]] "
           "[--preview SCALE[,CUT] [--preview-drag]] [--pixel X,Y] [--json]\n"
           "  speculum bench PROJECT --out DIR [--quick] [--convergence] [--size WxH] [--shard K/N "
           "[--contiguous]] [--keep-going]\n"
           "  speculum bench PROJECT --merge DIR... --out DIR\n"
           "  speculum time PROJECT [--size WxH] [--frames N] [--animated] [--time T] [--half-float] "
           "[--json]\n"
           "  speculum export PROJECT -o OUT.glb|OUT.gltf [--keep-going]\n"
           "\n"
           "render writes PNG, JPEG, TIFF, EXR or another format OpenImageIO writes (by the extension of\n"
           "OUT); --size defaults to 1280x720,\n"
           "--ssaa N averages NxN samples per pixel (1..16), --time evaluates animations at T seconds.\n"
           "--reference draws the still with the exact ray tracer; --samples N (1..65536, default 16) paths\n"
           "per sample average rough reflections, and the noise left is printed.\n"
           "--screen-space-sources draws each screen-space mirror in the colour of where its reflection\n"
           "comes from: green, met in the image; blue, the reflector's map; red, the background.\n"
           "--frames A..B renders an animation, frame N at N / fps seconds (--fps, default 24), into an\n"
           "image sequence (OUT with a frame number: frames/shot_%04d.png) or a clip (.mp4 H.264, .webm\n"
           "VP9, .gif); --turntable SECONDS orbits the camera about its target once in SECONDS (a seamless\n"
           "loop; without --frames, SECONDS x fps frames). --shard K/N renders the Kth (from 0) of N\n"
           "interleaved shares of the frames (contiguous with --contiguous) into the sequence; join encodes\n"
           "a finished sequence into a clip and refuses one with missing or mismatched frames.\n"
           "explain renders a frame and lists the passes that ran and the effects skipped, with reasons;\n"
           "--frame N explains the Nth of N identical frames, showing what a static scene reuses;\n"
           "--animated plays them 1/60 s apart from --time, as the playing editor draws them.\n"
           "--preview SCALE[,CUT] explains the frame as the editor previews it while the view moves: drawn\n"
           "at SCALE (0.125..1) of the width and height, CUT levels of mirror nesting left out, the\n"
           "environment map held; --preview-drag as while a handle is dragged (shadow maps drawn smaller).\n"
           "--pixel X,Y explains one pixel (x from the left, y from the top): the path the exact tracer\n"
           "follows to it, the passes that wrote it in the raster with the colour each left, and the error\n"
           "between the two with the causes they name.\n"
           "bench sweeps the settings the scene uses (map type and resolution, parallax, mirror technique "
           "and\n"
           "depth, PCF, tessellation), times each and measures its error against the exact tracer; it "
           "writes\n"
           "results.csv, results.json, plots and report.md into DIR. --quick: fewer points at 480x270.\n"
           "--shard K/N measures the Kth (from 0) of N shares of the configurations; --merge joins the\n"
           "shards' folders into one results set and report in --out.\n"
           "--convergence also traces the reference at 4, 16, 64, 256 (and 1024) paths per rough pixel and\n"
           "picks the count whose noise is below a tenth of the smallest error the run measured.\n"
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
           "a model, a texture) is refused. Exit status: 0 done, 1 failed, 2 bad command line.\n"
           "Every command takes --help (its own options), -q/--quiet (no progress on stderr) and\n"
           "--opt=value as well as --opt value.\n";
}

namespace {

// What `speculum COMMAND --help` says above the options.
const char* describe(Command command) {
    switch (command) {
    case Command::Render:
        return "Writes a still of PROJECT to OUT, in the format of its extension: PNG, JPEG, TIFF, EXR or "
               "any "
               "other format OpenImageIO writes (WebP, Targa, Radiance HDR, ...); with --frames or "
               "--turntable, an "
               "animation: an image sequence or a clip (.mp4, .webm, .gif).";
    case Command::Explain:
        return "Renders a frame of PROJECT and lists the passes that ran and the effects skipped, with "
               "reasons and times.";
    case Command::Bench:
        return "Sweeps the settings PROJECT uses, times each and measures its error against the exact "
               "tracer; writes results.csv, results.json, plots and report.md into DIR.";
    case Command::Time:
        return "Draws frames of PROJECT into an 8-bit target like a window's and prints the median, "
               "minimum and maximum frame time and each pass kind's share.";
    case Command::Export:
        return "Writes PROJECT as glTF 2.0: OUT.glb (one file) or OUT.gltf (with its .bin and images).";
    case Command::Join:
        return "Encodes a finished image sequence (SEQUENCE: its name with the frame number, "
               "frames/shot_%04d.png) into a clip: .mp4 (H.264), .webm (VP9) or .gif.";
    case Command::Editor:
    case Command::Help:
    case Command::Version:
        break;
    }
    return "";
}

// The values of a command's options as typed: checked after parsing, with the same messages whatever
// form they came in (--size 64x36, --size=64x36).
// explain --pixel X,Y: a pixel inside the frame's size (--size, parsed before it).
base::Status parsePixel(const std::string& text, CliOptions& o) {
    static const std::regex pixel(R"((\d+),(\d+))");
    std::smatch m;
    if (!std::regex_match(text, m, pixel))
        return Error{"--pixel: expected X,Y such as 640,360, got " + base::quoted(text)};
    auto x = parseInt("--pixel x", m[1].str(), 0, std::numeric_limits<int>::max());
    auto y = parseInt("--pixel y", m[2].str(), 0, std::numeric_limits<int>::max());
    if (!x || !y || *x >= o.width || *y >= o.height)
        return Error{"--pixel: " + base::quoted(text) + " is outside the " + std::to_string(o.width) + "x" +
                     std::to_string(o.height) + " image (x 0.." + std::to_string(o.width - 1) + ", y 0.." +
                     std::to_string(o.height - 1) + ")"};
    if (o.preview.active())
        return Error{"--pixel: not with --preview (a pixel is explained in the frame at rest)"};
    o.pixel = glm::ivec2(*x, *y);
    return base::Done{};
}

struct Typed {
    std::string size, ssaa, time, frame, frames, samples, preview, pixel;
    std::string frameRange, fps, turntable, shard;
    bool contiguous = false;
};

// --frames A..B: both frame numbers included, A <= B.
base::Status parseFrameRange(const std::string& text, CliOptions& o) {
    static const std::regex range(R"((\d+)\.\.(\d+))");
    std::smatch m;
    if (!std::regex_match(text, m, range))
        return Error{"--frames: expected A..B such as 0..239 (frame numbers, both included), got " +
                     base::quoted(text)};
    auto first = parseInt("--frames A", m[1].str(), 0, 9999999);
    if (!first)
        return Error{first.error()};
    auto last = parseInt("--frames B", m[2].str(), 0, 9999999);
    if (!last)
        return Error{last.error()};
    if (*last < *first)
        return Error{"--frames: " + base::quoted(text) + " is empty: B comes before A (A..B with A <= B)"};
    o.frameRange = std::pair{*first, *last};
    return base::Done{};
}

// render's and join's animation options: --frames A..B, --fps, --turntable, --shard K/N [--contiguous].
base::Status checkAnimationValues(const Typed& t, CliOptions& o) {
    if (!t.frameRange.empty())
        if (base::Status range = parseFrameRange(t.frameRange, o); !range)
            return range;
    if (!t.fps.empty()) {
        auto fps = parseInt("--fps", t.fps, 1, 240);
        if (!fps)
            return Error{fps.error()};
        o.fps = *fps;
        o.fpsGiven = true;
    }
    if (!t.turntable.empty()) {
        double seconds = 0.0;
        const auto [end, ec] = std::from_chars(t.turntable.data(), t.turntable.data() + t.turntable.size(),
                                               seconds, std::chars_format::general);
        if (ec != std::errc() || end != t.turntable.data() + t.turntable.size() || !std::isfinite(seconds))
            return Error{"--turntable: expected the seconds of one turn, got " + base::quoted(t.turntable)};
        if (seconds < 0.1 || seconds > 86400.0)
            return Error{"--turntable: " + base::quoted(t.turntable) +
                         " is out of range (0.1..86400 seconds)"};
        o.turntable = seconds;
        if (!o.frameRange) {
            const long long frames = std::llround(seconds * o.fps);
            if (frames > 10000000)
                return Error{"--turntable: " + base::quoted(t.turntable) + " seconds at " +
                             std::to_string(o.fps) + " fps is more than 10000000 frames"};
            o.frameRange = std::pair{0, static_cast<int>(std::max(1ll, frames) - 1)};
        }
    }
    if (!t.shard.empty()) {
        auto shard = base::parseShard("--shard", t.shard);
        if (!shard)
            return Error{shard.error()};
        shard->contiguous = t.contiguous;
        o.shard = *shard;
    } else if (t.contiguous) {
        return Error{"--contiguous: only with --shard K/N"};
    }
    if (o.command == Command::Render && !o.frameRange) {
        for (const auto& [given, name] : {std::pair{!t.fps.empty(), "--fps"}, {!t.shard.empty(), "--shard"}})
            if (given)
                return Error{std::string(name) + ": only with --frames A..B or --turntable SECONDS"};
    }
    if (o.command == Command::Render && o.frameRange && !t.time.empty())
        return Error{"--time: not with --frames (frame N shows the scene at N / fps seconds)"};
    return base::Done{};
}

base::Status checkValues(const Typed& t, CliOptions& o) {
    if (!t.size.empty()) {
        static const std::regex size(R"((\d+)[xX](\d+))");
        std::smatch m;
        if (!std::regex_match(t.size, m, size))
            return Error{"--size: expected WIDTHxHEIGHT such as 1280x720, got " + base::quoted(t.size)};
        // No limit per side: stills larger than the GPU's limits render in tiles. Only sizes whose pixels
        // would not fit in memory are refused, here, before any work.
        constexpr int kMaxSide = std::numeric_limits<int>::max();
        auto w = parseInt("--size width", m[1].str(), 1, kMaxSide);
        if (!w)
            return Error{w.error()};
        auto h = parseInt("--size height", m[2].str(), 1, kMaxSide);
        if (!h)
            return Error{h.error()};
        if (base::Status fits = render::checkStillSize(*w, *h); !fits)
            return Error{"--size: " + fits.error()};
        o.width = *w;
        o.height = *h;
        o.sizeGiven = true;
    }
    if (!t.ssaa.empty()) {
        auto n = parseInt("--ssaa", t.ssaa, render::kMinSsaa, render::kMaxSsaa);
        if (!n)
            return Error{n.error()};
        o.ssaa = *n;
    }
    if (!t.samples.empty()) {
        auto n = parseInt("--samples", t.samples, render::reference::kMinTraceSamples,
                          render::reference::kMaxTraceSamples);
        if (!n)
            return Error{n.error()};
        if (!o.reference)
            return Error{"--samples: only with --reference (the tracer's paths per rough reflection)"};
        o.samples = *n;
    }
    if (o.screenSpaceSources && o.reference)
        return Error{"--screen-space-sources: not with --reference (the tracer has no screen-space trace)"};
    if (!t.time.empty()) {
        auto seconds = parseTime(t.time);
        if (!seconds)
            return Error{seconds.error()};
        o.time = *seconds;
    }
    if (!t.frame.empty()) {
        auto n = parseInt("--frame", t.frame, 1, 100);
        if (!n)
            return Error{n.error()};
        o.frame = *n;
    }
    if (!t.preview.empty())
        if (base::Status preview = parsePreview(t.preview, o.preview); !preview)
            return preview;
    if (o.preview.redrawsShadows && t.preview.empty())
        return Error{"--preview-drag: only with --preview (a handle drag's preview)"};
    if (!t.pixel.empty())
        if (base::Status pixel = parsePixel(t.pixel, o); !pixel)
            return pixel;
    if (base::Status animation = checkAnimationValues(t, o); !animation)
        return animation;
    if (!t.frames.empty()) {
        auto n = parseInt("--frames", t.frames, 1, 100000);
        if (!n)
            return Error{n.error()};
        o.frames = *n;
    }
    return base::Done{};
}

// The option an error message is about: CLI11 names it first ("--size: 1 required TEXT missing").
std::string optionNamed(const std::string& what) {
    const std::size_t dash = what.find("-");
    if (dash == std::string::npos)
        return {};
    const std::size_t end = what.find_first_of(": ", dash);
    return what.substr(dash, end == std::string::npos ? std::string::npos : end - dash);
}

// How often the command line names `option` (as --name, --name=VALUE, -n or -nVALUE).
int timesGiven(const CLI::Option& option, const std::vector<std::string>& words) {
    int times = 0;
    for (const std::string& word : words) {
        for (const std::string& name : option.get_lnames())
            times += word == "--" + name || word.starts_with("--" + name + "=") ? 1 : 0;
        for (const std::string& name : option.get_snames())
            times += word.starts_with("-" + name) && !word.starts_with("--") ? 1 : 0;
    }
    return times;
}

// Options that take a value, given twice (which of the two was meant?) or with an empty one (''),
// refused with the option's name before any value is read.
base::Status checkGivenOnceWithAValue(const CLI::App& app, const std::vector<std::string>& words,
                                      bool parsed) {
    for (const CLI::Option* option : app.get_options()) {
        if (option->get_expected_min() == 0 || option->get_positional())
            continue; // a flag, or PROJECT
        const std::string name = option->get_name(false, false);
        if (!parsed && timesGiven(*option, words) > 1)
            return Error{name + ": given more than once"};
        if (parsed && option->count() > 0 &&
            std::all_of(option->results().begin(), option->results().end(),
                        [](const std::string& value) { return value.empty(); }))
            return Error{name + ": missing value"};
    }
    return base::Done{};
}

// render's and join's animation options.
void addAnimationOptions(CLI::App& app, Typed& typed, Command command) {
    app.add_option("--frames", typed.frameRange,
                   command == Command::Render ? "Render frames A to B of the animation (N at N / fps seconds)"
                                              : "The frames the sequence must hold (default: those on disk)")
        ->type_name("A..B");
    app.add_option("--fps", typed.fps, "Frames per second (1..240, default 24)")->type_name("N");
    if (command != Command::Render)
        return;
    app.add_option("--turntable", typed.turntable,
                   "Orbit the camera about its target once in SECONDS (a seamless loop; without --frames, "
                   "SECONDS x fps frames)")
        ->type_name("SECONDS");
    app.add_option("--shard", typed.shard, "Render the Kth (from 0) of N interleaved shares of the frames")
        ->type_name("K/N");
    app.add_flag("--contiguous", typed.contiguous, "With --shard: a contiguous share, not every Nth frame");
}

// explain's own options: which frame, and which preview of it.
void addExplainOptions(CLI::App& app, Typed& typed, CliOptions& o) {
    app.add_option("--frame", typed.frame, "Explain the Nth of N identical frames (1..100)")->type_name("N");
    app.add_flag("--animated", o.animated,
                 "With --frame: play the N frames 1/60 s apart from --time, as the playing editor does");
    app.add_option("--preview", typed.preview,
                   "Explain the editor's preview: SCALE (0.125..1) of the width and height, CUT mirror "
                   "levels left out, the environment map held")
        ->type_name("SCALE[,CUT]");
    app.add_option("--pixel", typed.pixel,
                   "Explain one pixel (X from the left, Y from the top): its exact path beside the raster's "
                   "recipe")
        ->type_name("X,Y");
    app.add_flag("--preview-drag", o.preview.redrawsShadows,
                 "With --preview: as while a handle is dragged (shadow maps drawn smaller)");
}

// What a command reads and writes: PROJECT (join: SEQUENCE), -o (bench: --out), and the options that
// choose which frames or configurations (render and join: --frames and their kin; bench: --shard, --merge).
void addTargetOptions(CLI::App& app, Typed& typed, CliOptions& o, Command command) {
    if (command == Command::Join)
        app.add_option("SEQUENCE", o.project, "The image sequence: its name with the frame number")
            ->type_name("");
    else
        app.add_option("PROJECT", o.project, "The project file (*.speculum.json)")->type_name("");
    if (command == Command::Render || command == Command::Export || command == Command::Join)
        app.add_option("-o,--output", o.output,
                       command == Command::Render
                           ? "The image to write (.png, .jpg, .tif, .exr, .webp, ...), "
                             "or with --frames a sequence (shot_%04d.png) or a clip "
                             "(.mp4, .webm, .gif)"
                       : command == Command::Export ? "The glTF file to write (.glb or .gltf)"
                                                    : "The clip to write (.mp4, .webm, .gif)")
            ->type_name(command == Command::Join ? "CLIP" : "OUT");
    if (command == Command::Render || command == Command::Join)
        addAnimationOptions(app, typed, command);
    if (command == Command::Bench) {
        app.add_option("--shard", typed.shard, "Measure the Kth (from 0) of N shares of the configurations")
            ->type_name("K/N");
        app.add_flag("--contiguous", typed.contiguous, "With --shard: a contiguous share, not every Nth");
        app.add_option("--merge", o.mergeDirs, "Join these shards' result folders into --out")
            ->type_name("DIR...")
            ->expected(1, 100000);
    }
    if (command == Command::Bench)
        app.add_option("--out", o.outDir, "The folder for the results (made if missing)")->type_name("DIR");
}

// One command's options, parsed by CLI11: --opt value and --opt=value alike, -h/--help for the command's
// own help. Values are kept as typed and checked by checkValues, so every form gets the same message.
base::Result<CliOptions> parseCommand(Command command, const std::string& name,
                                      const std::vector<std::string>& rest) {
    CliOptions o;
    o.command = command;
    Typed typed;
    CLI::App app(describe(command), "speculum " + name);
    app.set_help_flag("-h,--help", "Print this help and exit");
    // Unknown words are checked below, to name them the way every other error of speculum does.
    app.allow_extras();
    addTargetOptions(app, typed, o, command);
    const bool renders = command == Command::Render || command == Command::Explain;
    if (renders || command == Command::Time || command == Command::Bench)
        app.add_option("--size", typed.size, "WIDTHxHEIGHT of the frame (default 1280x720)")
            ->type_name("WxH");
    if (command == Command::Render) {
        app.add_option("--ssaa", typed.ssaa, "Average NxN samples per pixel (1..16)")->type_name("N");
        app.add_flag("--reference", o.reference, "Draw the still with the exact tracer");
        app.add_option("--samples", typed.samples,
                       "With --reference: paths per sample through rough reflections (1..65536, default 16)")
            ->type_name("N");
        app.add_flag("--screen-space-sources", o.screenSpaceSources,
                     "Draw screen-space mirrors in the colour of where their reflection comes from (green: "
                     "the image, blue: the reflector's map, red: the background)");
    }
    if (renders || command == Command::Time)
        app.add_option("--time", typed.time, "Evaluate animations at T seconds (default 0)")->type_name("T");
    if (command == Command::Explain)
        addExplainOptions(app, typed, o);
    if (command == Command::Explain || command == Command::Time)
        app.add_flag("--json", o.json, "Print JSON");
    if (command == Command::Time) {
        app.add_option("--frames", typed.frames, "Frames timed after 5 warm-up frames (default 100)")
            ->type_name("N");
        app.add_flag("--animated", o.animated, "Play the animation at 60 frames a second");
        app.add_flag("--half-float", o.halfFloat, "Draw through the half-float buffer, to compare");
    }
    if (command == Command::Bench) {
        app.add_flag("--quick", o.quick, "Fewer points at 480x270");
        app.add_flag("--convergence", o.convergence,
                     "Also trace the reference at rising paths per rough pixel and pick the count it needs");
    }
    if (command != Command::Explain && command != Command::Join)
        app.add_flag("--keep-going", o.keepGoing, "A missing or unreadable model or texture is a warning");
    app.add_flag("-q,--quiet", o.quiet, "No progress on stderr (warnings and errors still)");

    if (base::Status once = checkGivenOnceWithAValue(app, rest, false); !once)
        return Error{once.error()};
    std::vector<std::string> reversed(rest.rbegin(), rest.rend()); // CLI11 reads the vector from its back
    try {
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        o.command = Command::Help;
        o.helpText = app.help();
        return o;
    } catch (const CLI::ParseError& e) {
        const std::string option = optionNamed(e.what());
        if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) && !option.empty())
            return Error{option + ": missing value"};
        return Error{name + ": " + base::printable(e.what(), 200) + " (see speculum " + name + " --help)"};
    }
    for (const std::string& extra : app.remaining()) {
        if (!extra.empty() && extra[0] == '-')
            return Error{name + ": unknown option " + base::quoted(extra) + " (see speculum " + name +
                         " --help)"};
        return Error{name + ": unexpected argument " + base::quoted(extra)};
    }
    if (base::Status once = checkGivenOnceWithAValue(app, rest, true); !once)
        return Error{once.error()};
    if (base::Status values = checkValues(typed, o); !values)
        return Error{values.error()};
    if (o.project.empty())
        return Error{name + (command == Command::Join ? ": missing SEQUENCE" : ": missing PROJECT file")};
    if (command == Command::Join && o.output.empty())
        return Error{"join: missing -o CLIP"};
    if (!o.mergeDirs.empty() && o.shard)
        return Error{"--merge: not with --shard (merge the shards' folders once they are done)"};
    if (command == Command::Render && o.output.empty())
        return Error{"render: missing -o OUT"};
    if (command == Command::Export && o.output.empty())
        return Error{"export: missing -o OUT.glb|OUT.gltf"};
    if (command == Command::Bench && o.outDir.empty())
        return Error{"bench: missing --out DIR"};
    return o;
}

} // namespace

namespace {

constexpr std::pair<const char*, Command> kNamed[] = {
    {"render", Command::Render}, {"explain", Command::Explain}, {"bench", Command::Bench},
    {"export", Command::Export}, {"time", Command::Time},       {"join", Command::Join}};

} // namespace

std::string commandWord(Command command) {
    for (const auto& [word, named] : kNamed)
        if (named == command)
            return word;
    return "speculum";
}

base::Result<CliOptions> parseCommandLine(const std::vector<std::string>& args) {
    CliOptions o;
    if (args.empty())
        return o;
    const std::string& first = args[0];
    if (first == "-h" || first == "--help" || first == "help") {
        o.command = Command::Help;
        o.helpText = usageText();
        return o;
    }
    if (first == "--version") {
        o.command = Command::Version;
        return o;
    }
    for (const auto& [word, command] : kNamed)
        if (first == word)
            return parseCommand(command, first, std::vector<std::string>(args.begin() + 1, args.end()));
    if (first == "--recover") {
        if (args.size() != 2 || args[1].empty())
            return Error{"--recover takes one recovery file"};
        o.recover = args[1];
        return o;
    }
    if (!first.empty() && first[0] == '-')
        return Error{"unknown option " + base::quoted(first) + " (see speculum --help)"};
    if (looksLikeCommand(first, args.size()))
        return Error{unknownCommand(first)};
    if (args.size() > 1)
        return Error{"the editor takes one project file, got " + std::to_string(args.size())};
    o.project = first;
    return o;
}

} // namespace speculum::app
