#include "scene/export/AnimationExport.hpp"

#include "base/AtomicFile.hpp"
#include "base/Printable.hpp"
#include "render/image/ColorSpace.hpp"
#include "render/video/VideoWriter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace speculum::scene {

namespace {

using Clock = std::chrono::steady_clock;

// The one frame number of a pattern: %d or %0Nd.
const std::regex& frameNumber() {
    static const std::regex number("%(0[1-9])?d");
    return number;
}

// What the renderer must have drawn before a frame for its maps to be where a clip drawn from its first
// frame has them: nothing when every map is drawn from the frame alone (redrawn always, or when what it
// sees changes, and every shadow map so), the clip's first frame when a map is drawn once, and every
// earlier frame when a map is time-sliced (which face it redraws depends on the faces before).
enum class MapHistory { None, FirstFrame, EveryFrame };

MapHistory mapHistory(const render::FrameInput& input) {
    MapHistory history = MapHistory::None;
    for (const render::Reflector& r : input.reflectors) {
        if (r.update == render::ReflectorUpdate::TimeSliced)
            return MapHistory::EveryFrame;
        if (r.update == render::ReflectorUpdate::Once)
            history = MapHistory::FirstFrame;
    }
    return history;
}

std::vector<std::uint8_t> toSrgb8(const render::Image& image) {
    std::vector<std::uint8_t> bytes(image.rgba.size());
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = (i % 4 == 3) ? 255 : render::linearToSrgb8(image.rgba[i]);
    return bytes;
}

// The project by its file's name and contents (FNV-1a), not its path: the shards of one clip on machines
// that mount the project in other places, or name it by another relative path, draw the same clip.
std::string projectIdentity(const std::string& projectPath) {
    if (projectPath.empty())
        return "untitled";
    std::ifstream in(projectPath, std::ios::binary);
    std::uint64_t hash = 14695981039346656037ull;
    for (char c; in.get(c);)
        hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    std::ostringstream text;
    text << std::filesystem::path(projectPath).filename().string() << " (" << std::hex << hash << ")";
    return text.str();
}

// The settings every frame of one clip shares, stored in each frame ("speculum:clip") so that `join`
// can refuse frames of another clip.
std::string clipFingerprint(const std::string& projectPath, const AnimationSettings& s) {
    std::ostringstream text;
    text << "scene " << projectIdentity(projectPath) << "; size " << s.still.width << "x" << s.still.height
         << "; ssaa " << s.still.ssaa << "; "
         << (s.still.reference ? "reference, " + std::to_string(s.still.samples) + " paths" : "raster")
         << "; fps " << s.fps;
    if (s.turntableSeconds)
        text << "; turntable " << *s.turntableSeconds << " s";
    return text.str();
}

// A frame's attributes: the still's (software, scene, settings, renderer) without its render time, so
// that the same frame drawn on another run or machine is the same file; the frame's number and time, and
// the clip's fingerprint.
render::ImageMetadata frameMetadata(const std::string& projectPath, const AnimationSettings& settings,
                                    StillExportSettings still, const StillExportResult& result, int frame) {
    render::ImageMetadata metadata = stillMetadata(projectPath, still, result);
    std::erase_if(metadata.attributes, [](const auto& a) {
        return a.first == "speculum:renderTimeMs" || a.first == "speculum:noiseRms";
    });
    metadata.attributes.emplace_back("speculum:frame", std::to_string(frame));
    metadata.attributes.emplace_back("speculum:fps", std::to_string(settings.fps));
    metadata.attributes.emplace_back("speculum:clip", clipFingerprint(projectPath, settings));
    return metadata;
}

// The frames of the export, in order: the shard's share of the range.
std::vector<int> framesToDraw(const AnimationSettings& settings) {
    std::vector<int> frames;
    for (int i : base::shardItems(settings.shard, settings.frames.count()))
        frames.push_back(settings.frames.first + i);
    return frames;
}

std::string rangeText(int first, int last) {
    return first == last ? std::to_string(first) : std::to_string(first) + ".." + std::to_string(last);
}

// The frame after `frame` in `frames`.
int nextAfter(const std::vector<int>& frames, int frame) {
    const auto it = std::upper_bound(frames.begin(), frames.end(), frame);
    return it == frames.end() ? frame + 1 : *it;
}

// One export in progress: the frame loop's state.
class AnimationRun {
public:
    AnimationRun(render::Renderer* renderer, const FrameSource& source, const std::string& projectPath,
                 const AnimationSettings& settings, const AnimationOutput& output,
                 const AnimationProgressCallback& progress, const std::string& rendererDescription)
        : m_renderer(renderer)
        , m_source(source)
        , m_project(projectPath)
        , m_settings(settings)
        , m_output(output)
        , m_progress(progress)
        , m_description(rendererDescription) {}

    AnimationResult run();

private:
    render::FrameInput frameAt(int frame) const;
    StillExportSettings stillAt(int frame) const;
    base::Result<StillExportResult> draw(int frame, double doneBefore);
    base::Status bringMapsTo(int frame);
    base::Status writeFrame(int frame, const StillExportResult& drawn);
    bool report(int frame, double withinFrame);
    base::Status prepareShardRecords();
    base::Status prepare(const std::vector<int>& frames);
    base::Status drawAndWrite(int frame);
    void stopped(const base::Status& why, int frame);
    std::string keptAndResume(int frame) const;

    render::Renderer* m_renderer;
    const FrameSource& m_source;
    std::string m_project;
    const AnimationSettings& m_settings;
    const AnimationOutput& m_output;
    const AnimationProgressCallback& m_progress;
    std::string m_description;
    std::unique_ptr<render::video::VideoWriter> m_video;
    AnimationResult m_result;
    Clock::time_point m_start = Clock::now();
    std::optional<int> m_lastDrawn; // the last frame the renderer drew, written or replayed
    MapHistory m_history = MapHistory::None;
    int m_total = 0;
    bool m_cancelled = false;
};

render::FrameInput AnimationRun::frameAt(int frame) const {
    const double time = frameTime(m_settings, frame);
    render::FrameInput input = m_source(time);
    if (m_settings.still.camera)
        input.camera = *m_settings.still.camera;
    if (m_settings.turntableSeconds)
        input.camera = turntableCamera(input.camera, *m_settings.turntableSeconds, time);
    return input;
}

StillExportSettings AnimationRun::stillAt(int frame) const {
    StillExportSettings still = m_settings.still;
    still.time = frameTime(m_settings, frame);
    return still;
}

bool AnimationRun::report(int frame, double withinFrame) {
    if (!m_progress)
        return true;
    AnimationProgress p;
    p.done = static_cast<int>(m_result.written.size());
    p.total = m_total;
    p.frame = frame;
    p.fraction = m_total > 0 ? std::min(1.0, (p.done + std::clamp(withinFrame, 0.0, 1.0)) / m_total) : 1.0;
    p.elapsedSeconds = std::chrono::duration<double>(Clock::now() - m_start).count();
    if (p.done > 0 && p.fraction > 0.0)
        p.remainingSeconds = p.elapsedSeconds * (1.0 - p.fraction) / p.fraction;
    if (!m_progress(p))
        m_cancelled = true;
    return !m_cancelled;
}

base::Result<StillExportResult> AnimationRun::draw(int frame, double /*doneBefore*/) {
    const render::ProgressCallback within = [&](double fraction, const std::string&) {
        return report(frame, fraction);
    };
    const render::FrameInput input = frameAt(frame);
    auto drawn = renderStillImage(m_renderer, input, stillAt(frame), within, m_description);
    if (drawn)
        m_lastDrawn = frame;
    return drawn;
}

// A shard's raster frame that follows a gap: the frames the maps depend on are drawn first, unwritten.
base::Status AnimationRun::bringMapsTo(int frame) {
    if (m_settings.still.reference || m_history == MapHistory::None)
        return base::Done{};
    std::vector<int> replay;
    if (m_history == MapHistory::FirstFrame && !m_lastDrawn && frame != m_settings.frames.first)
        replay.push_back(m_settings.frames.first);
    if (m_history == MapHistory::EveryFrame)
        for (int f = m_lastDrawn ? *m_lastDrawn + 1 : m_settings.frames.first; f < frame; ++f)
            replay.push_back(f);
    for (int f : replay) {
        auto drawn = draw(f, 0.0);
        if (!drawn)
            return base::Error{drawn.error()};
        ++m_result.replayed;
    }
    return base::Done{};
}

base::Status AnimationRun::writeFrame(int frame, const StillExportResult& drawn) {
    if (m_video)
        return m_video->write(toSrgb8(drawn.still.image));
    const std::string path = sequenceFramePath(m_output.path, frame);
    if (base::Status written = render::writeImage(
            path, drawn.still.image, frameMetadata(m_project, m_settings, stillAt(frame), drawn, frame));
        !written)
        return written;
    m_result.files.push_back(path);
    return base::Done{};
}

// A sequence's shard checks the records of the other shards and leaves its own; a whole render replaces
// them all.
base::Status AnimationRun::prepareShardRecords() {
    if (m_output.video)
        return base::Done{};
    if (m_settings.shard.whole())
        return base::Done{};
    if (base::Status agree = checkShardRecords(m_output.path, m_settings.frames, m_settings.shard); !agree)
        return agree;
    return recordShard(m_output.path, m_settings.frames, m_settings.shard);
}

// Why the export stopped before `frame`, and for a sequence what it kept and where to resume.
void AnimationRun::stopped(const base::Status& why, int frame) {
    m_result.cancelled = m_cancelled;
    std::string message = m_cancelled ? std::string("cancelled") : why.error();
    for (const std::string unwritten : {"; nothing was written", "; no clip was written"})
        if (message.ends_with(unwritten)) // the frame or clip that failed says so itself; said once below
            message.resize(message.size() - unwritten.size());
    if (m_output.video) {
        m_result.outcome = "no clip was written";
    } else {
        m_result.resumeFrom = frame;
        m_result.outcome = keptAndResume(frame);
    }
    m_result.status = base::Error{message + "; " + m_result.outcome};
}

// What a sequence that stopped before `frame` kept, and how to finish it. A range resumes from `frame`
// where nothing carries between frames; where maps do (time-sliced, drawn once), the frames before
// `frame` must be drawn again for its maps, and a shard's share is its own: both run again whole.
std::string AnimationRun::keptAndResume(int frame) const {
    const std::vector<int>& kept = m_result.written;
    std::string text;
    if (kept.empty())
        text = "no frame was written";
    else if (m_settings.shard.whole())
        text = "frames " + rangeText(kept.front(), kept.back()) + " are kept";
    else
        text = std::to_string(kept.size()) + (kept.size() == 1 ? " frame" : " frames") + " of shard " +
               base::shardText(m_settings.shard) + " are kept";
    if (!m_settings.shard.whole())
        return text + "; run the same command again to finish the shard";
    if (m_history != MapHistory::None && !m_settings.still.reference)
        return text + "; run the same command again (the maps of frame " + std::to_string(frame) +
               " depend on the frames before it)";
    return text + "; resume with --frames " + rangeText(frame, m_settings.frames.last);
}

// Everything before the first frame: the checks, the shards' records, what the maps carry between
// frames, and for a clip its encoder.
base::Status AnimationRun::prepare(const std::vector<int>& frames) {
    if (base::Status valid = validateAnimationExport(m_settings, m_output); !valid)
        return valid;
    if (frames.empty())
        return base::Error{"shard " + base::shardText(m_settings.shard) + " of " +
                           std::to_string(m_settings.frames.count()) + " frames has none to draw"};
    if (base::Status shards = prepareShardRecords(); !shards)
        return shards;
    if (!m_settings.still.reference)
        m_history = mapHistory(frameAt(m_settings.frames.first));
    if (!m_output.video)
        return base::Done{};
    render::video::VideoWriter::Settings video{
        m_settings.still.width, m_settings.still.height, m_settings.fps, {}};
    video.metadata = {{"title", m_project.empty() ? std::string("untitled scene")
                                                  : std::filesystem::path(m_project).filename().string()},
                      {"comment", "speculum " + std::string(SPECULUM_VERSION) + ": " +
                                      clipFingerprint(m_project, m_settings)}};
    auto writer = render::video::VideoWriter::open(m_output.path, *m_output.video, video);
    if (!writer)
        return base::Error{writer.error()};
    m_video = std::move(*writer);
    return base::Done{};
}

// One frame: the maps brought to where the clip has them, the frame drawn and written.
base::Status AnimationRun::drawAndWrite(int frame) {
    if (!report(frame, 0.0))
        return base::Error{"cancelled"};
    if (base::Status replayed = bringMapsTo(frame); !replayed)
        return replayed;
    auto drawn = draw(frame, 0.0);
    if (!drawn)
        return base::Error{drawn.error()};
    for (const std::string& w : drawn->warnings)
        if (std::find(m_result.warnings.begin(), m_result.warnings.end(), w) == m_result.warnings.end())
            m_result.warnings.push_back(w);
    m_result.renderer = drawn->renderer;
    m_result.totalMs += drawn->still.totalMs;
    return writeFrame(frame, *drawn);
}

AnimationResult AnimationRun::run() {
    if (base::Status valid = validateAnimationExport(m_settings, m_output); !valid) {
        m_result.status = valid;
        return m_result;
    }
    const std::vector<int> frames = framesToDraw(m_settings);
    m_total = static_cast<int>(frames.size());
    if (base::Status prepared = prepare(frames); !prepared) {
        m_result.status = prepared;
        return m_result;
    }
    for (int frame : frames) {
        if (base::Status step = drawAndWrite(frame); !step) {
            stopped(step, frame);
            return m_result;
        }
        m_result.written.push_back(frame);
        if (m_cancelled && frame != frames.back()) { // a cancel that came as the frame was finished
            stopped(base::Error{"cancelled"}, nextAfter(frames, frame));
            return m_result;
        }
    }
    if (m_cancelled) { // a cancel as the last frame was finished: a clip is not committed after it
        stopped(base::Error{"cancelled"}, frames.back() + 1);
        return m_result;
    }
    if (!m_output.video && m_settings.shard.whole())
        clearShardRecords(m_output.path, m_settings.frames); // this render drew every frame itself
    if (m_video) {
        if (base::Status finished = m_video->finish(); !finished) {
            m_result.status = finished;
            return m_result;
        }
        m_result.files.push_back(m_output.path);
    }
    report(frames.back(), 1.0);
    return m_result;
}

} // namespace

base::Result<AnimationOutput> parseAnimationOutput(const std::string& out) {
    AnimationOutput output{out, render::video::videoFormatOf(out)};
    if (output.video)
        return output;
    const std::string name = std::filesystem::path(out).filename().string();
    const auto numbers =
        std::distance(std::sregex_iterator(name.begin(), name.end(), frameNumber()), std::sregex_iterator());
    const std::string example = sequenceFramePath(out, 0);
    if (!render::isSupportedImagePath(out))
        return base::Error{base::quoted(out) + ": unknown extension: a clip is " +
                           render::video::videoFormatList() +
                           "; an image sequence is a name with a frame number such as frames/shot_%04d.png"};
    if (out.find('%') < out.size() - name.size())
        return base::Error{base::quoted(out) +
                           ": the frame number belongs in the file's name, not its folder"};
    if (numbers == 0)
        return base::Error{base::quoted(out) +
                           ": an image sequence needs a frame number in its name, such as shot_%04d.png "
                           "(%d, or %0Nd for N digits); a clip is " +
                           render::video::videoFormatList()};
    if (numbers > 1 || std::count(name.begin(), name.end(), '%') != 1)
        return base::Error{base::quoted(out) +
                           ": an image sequence's name holds one frame number (%d or %0Nd) and no other %"};
    return output;
}

std::string sequenceFramePath(const std::string& pattern, int frame) {
    std::smatch m;
    if (!std::regex_search(pattern, m, frameNumber()))
        return pattern;
    std::string number = std::to_string(frame);
    const int width = m[1].matched ? std::stoi(m[1].str().substr(1)) : 0;
    if (static_cast<int>(number.size()) < width)
        number.insert(0, static_cast<std::size_t>(width) - number.size(), '0');
    return m.prefix().str() + number + m.suffix().str();
}

std::vector<int> framesOnDisk(const std::string& pattern) {
    std::smatch m;
    std::vector<int> frames;
    if (!std::regex_search(pattern, m, frameNumber()))
        return frames;
    const std::filesystem::path path(pattern);
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
    const std::string name = path.filename().string();
    std::smatch n;
    std::regex_search(name, n, frameNumber());
    const auto escape = [](const std::string& text) {
        return std::regex_replace(text, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
    };
    const int width = n[1].matched ? std::stoi(n[1].str().substr(1)) : 1;
    const std::regex file(escape(n.prefix().str()) + "([0-9]{" + std::to_string(width) + ",7})" +
                          escape(n.suffix().str()));
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string candidate = it->path().filename().string();
        std::smatch f;
        if (std::regex_match(candidate, f, file) &&
            sequenceFramePath(name, std::stoi(f[1].str())) == candidate)
            frames.push_back(std::stoi(f[1].str()));
    }
    std::sort(frames.begin(), frames.end());
    return frames;
}

namespace {

struct ShardRecord {
    std::string file;
    std::string shard;  // "1/3"
    std::string layout; // "frames 0..239, interleaved in 3"
};

std::string recordPrefix(const std::string& pattern) {
    return "." + std::filesystem::path(pattern).filename().string() + ".shard-";
}

std::filesystem::path folderOf(const std::string& pattern) {
    const std::filesystem::path path(pattern);
    return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

std::string layoutText(const FrameRange& frames, const base::Shard& shard) {
    return "frames " + std::to_string(frames.first) + ".." + std::to_string(frames.last) + ", " +
           (shard.contiguous ? "contiguous" : "interleaved") + " in " + std::to_string(shard.count);
}

std::vector<ShardRecord> shardRecords(const std::string& pattern) {
    std::vector<ShardRecord> records;
    const std::string prefix = recordPrefix(pattern);
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folderOf(pattern), ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::filesystem::path entry = it->path();
        const std::string name = entry.filename().string();
        if (!name.starts_with(prefix))
            continue;
        std::ifstream in(entry);
        ShardRecord record{entry.string(), {}, {}};
        std::getline(in, record.shard);
        std::getline(in, record.layout);
        record.shard =
            base::printable(record.shard, 40); // a record edited by hand stays one line in messages
        record.layout = base::printable(record.layout, 200);
        records.push_back(std::move(record));
    }
    std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) { return a.file < b.file; });
    return records;
}

} // namespace

base::Status checkShardRecords(const std::string& pattern, const FrameRange& frames,
                               const base::Shard& shard) {
    const std::string layout = layoutText(frames, shard);
    for (const ShardRecord& record : shardRecords(pattern))
        if (record.layout != layout)
            return base::Error{base::quoted(pattern) + " holds shard " + record.shard + " of " +
                               record.layout + "; shard " + base::shardText(shard) + " of " + layout +
                               " would overlap it or leave gaps (split the range the same way, or remove " +
                               base::quoted(record.file) + " and its frames)"};
    return base::Done{};
}

base::Status recordShard(const std::string& pattern, const FrameRange& frames, const base::Shard& shard) {
    const std::filesystem::path file =
        folderOf(pattern) /
        (recordPrefix(pattern) + std::to_string(shard.index) + "-of-" + std::to_string(shard.count));
    auto out = base::AtomicFile::create(file.string());
    if (!out)
        return base::Error{out.error()};
    if (base::Status written = out->write(std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                                          "\n" + layoutText(frames, shard) + "\n");
        !written)
        return written;
    return out->commit();
}

void clearShardRecords(const std::string& pattern, const FrameRange& frames) {
    const std::string range =
        "frames " + std::to_string(frames.first) + ".." + std::to_string(frames.last) + ",";
    for (const ShardRecord& record : shardRecords(pattern)) {
        if (!record.layout.starts_with(range))
            continue;
        std::error_code ec;
        std::filesystem::remove(record.file, ec);
    }
}

base::Status checkShardRecordsAgree(const std::string& pattern) {
    const std::vector<ShardRecord> records = shardRecords(pattern);
    for (const ShardRecord& record : records)
        if (record.layout != records.front().layout)
            return base::Error{"shard " + records.front().shard + " of " + records.front().layout +
                               " and shard " + record.shard + " of " + record.layout +
                               " both drew frames of this sequence: they overlap or leave gaps"};
    return base::Done{};
}

double frameTime(const AnimationSettings& settings, int frame) {
    return static_cast<double>(frame) / settings.fps;
}

render::Camera turntableCamera(const render::Camera& camera, double turnSeconds, double time) {
    const double turns = time / turnSeconds;
    const double angle = 2.0 * 3.14159265358979323846 * (turns - std::floor(turns));
    const glm::dvec3 axis = glm::normalize(camera.up);
    const glm::dvec3 offset = camera.position - camera.target;
    // Rodrigues' rotation of the offset about the up axis through the target.
    const glm::dvec3 rotated = offset * std::cos(angle) + glm::cross(axis, offset) * std::sin(angle) +
                               axis * glm::dot(axis, offset) * (1.0 - std::cos(angle));
    render::Camera turned = camera;
    turned.position = camera.target + rotated;
    return turned;
}

base::Status validateAnimationExport(const AnimationSettings& settings, const AnimationOutput& output) {
    const FrameRange& r = settings.frames;
    if (r.first < 0 || r.last > kMaxFrameNumber || r.last < r.first)
        return base::Error{"frames " + std::to_string(r.first) + ".." + std::to_string(r.last) +
                           ": the range is empty or reversed (frames A..B with 0 <= A <= B <= " +
                           std::to_string(kMaxFrameNumber) + ")"};
    if (settings.fps < render::video::kMinFps || settings.fps > render::video::kMaxFps)
        return base::Error{"fps " + std::to_string(settings.fps) + " is out of range (" +
                           std::to_string(render::video::kMinFps) + ".." +
                           std::to_string(render::video::kMaxFps) + ")"};
    if (settings.turntableSeconds && !(*settings.turntableSeconds > 0.0 && *settings.turntableSeconds <= 1e6))
        return base::Error{"a turntable's turn lasts more than 0 seconds"};
    if (output.video && !settings.shard.whole())
        return base::Error{"a shard writes an image sequence; join the finished sequence into a clip with "
                           "speculum join"};
    const std::string first = output.video ? output.path : sequenceFramePath(output.path, r.first);
    if (output.video) {
        if (auto ok = render::video::checkVideoTarget(*output.video, settings.still.width,
                                                      settings.still.height, settings.fps);
            !ok)
            return base::Error{base::printable(output.path, 200) + ": " + ok.error()};
        StillExportSettings still = settings.still;
        return validateStillExport(still, std::filesystem::path(first).replace_extension(".png").string());
    }
    return validateStillExport(settings.still, first);
}

AnimationResult exportAnimation(render::Renderer* renderer, const FrameSource& source,
                                const std::string& projectPath, const AnimationSettings& settings,
                                const AnimationOutput& output, const AnimationProgressCallback& progress,
                                const std::string& rendererDescription) {
    AnimationRun run(renderer, source, projectPath, settings, output, progress, rendererDescription);
    return run.run();
}

} // namespace speculum::scene
