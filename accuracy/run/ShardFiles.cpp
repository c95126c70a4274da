#include "accuracy/run/ShardFiles.hpp"

#include "accuracy/run/FamilyComparison.hpp"
#include "base/AtomicFile.hpp"
#include "base/Printable.hpp"

#include <QByteArray>
#include <QDataStream>
#include <QFile>
#include <functional>

namespace speculum::accuracy {

namespace {

// The file's first bytes and what follows them: a frame, or a reference.
constexpr quint32 kMagic = 0x53504246; // "SPBF"
constexpr qint32 kVersion = 1;
enum class Content : qint32 { Frame = 1, Reference = 2 };

void putImage(QDataStream& out, const render::Image& image) {
    out << qint32(image.width) << qint32(image.height) << quint64(image.rgba.size());
    for (float v : image.rgba)
        out << v;
}

bool getImage(QDataStream& in, render::Image& image) {
    qint32 width = 0, height = 0;
    quint64 count = 0;
    in >> width >> height >> count;
    if (in.status() != QDataStream::Ok || width < 0 || height < 0 ||
        count != quint64(width) * quint64(height) * 4 || count > quint64(in.device()->bytesAvailable()) / 4)
        return false;
    image.width = width;
    image.height = height;
    image.rgba.resize(count);
    for (float& v : image.rgba)
        in >> v;
    return in.status() == QDataStream::Ok;
}

void putMask(QDataStream& out, const std::vector<std::uint8_t>& mask) {
    out << quint64(mask.size());
    out.writeRawData(reinterpret_cast<const char*>(mask.data()), static_cast<int>(mask.size()));
}

bool getMask(QDataStream& in, std::vector<std::uint8_t>& mask) {
    quint64 size = 0;
    in >> size;
    if (in.status() != QDataStream::Ok || size > quint64(in.device()->bytesAvailable()))
        return false;
    mask.resize(size);
    return in.readRawData(reinterpret_cast<char*>(mask.data()), static_cast<int>(size)) == int(size);
}

QDataStream& setUp(QDataStream& stream) {
    stream.setVersion(QDataStream::Qt_6_0);
    stream.setByteOrder(QDataStream::LittleEndian);
    stream.setFloatingPointPrecision(QDataStream::SinglePrecision);
    return stream;
}

base::Status writeCompressed(const std::string& path, Content content,
                             const std::function<void(QDataStream&)>& fill) {
    QByteArray payload;
    {
        QDataStream out(&payload, QIODevice::WriteOnly);
        setUp(out) << kMagic << kVersion << qint32(content);
        fill(out);
    }
    const QByteArray compressed = qCompress(payload, 1); // fast: the floats hardly compress harder
    return base::writeFileAtomically(path, compressed.constData(),
                                     static_cast<std::size_t>(compressed.size()));
}

// The file's payload past its header, or the error that names what is wrong with it.
base::Result<QByteArray> readPayload(const std::string& path, Content content) {
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly))
        return base::Error{base::printable(path) + ": cannot read (" + file.errorString().toStdString() +
                           ")"};
    const QByteArray payload = qUncompress(file.readAll());
    QDataStream in(payload);
    quint32 magic = 0;
    qint32 version = 0, stored = 0;
    setUp(in) >> magic >> version >> stored;
    if (in.status() != QDataStream::Ok || magic != kMagic || version != kVersion || stored != qint32(content))
        return base::Error{base::printable(path) + ": not a " +
                           (content == Content::Frame ? "frame" : "reference") + " a bench shard wrote"};
    return payload;
}

} // namespace

std::string shardFrameFile(const std::string& configurationId) {
    return std::string(kShardFolder) + "/frame-" + configurationId + ".bin";
}

std::string shardReferenceFile(ReferenceKind kind) {
    return std::string(kShardFolder) + "/reference-" + referenceName(kind) + ".bin";
}

base::Status writeShardFrame(const std::string& path, const render::Image& frame) {
    return writeCompressed(path, Content::Frame, [&](QDataStream& out) { putImage(out, frame); });
}

base::Result<render::Image> readShardFrame(const std::string& path) {
    auto payload = readPayload(path, Content::Frame);
    if (!payload)
        return base::Error{payload.error()};
    QDataStream in(*payload);
    in.skipRawData(12); // the header readPayload checked
    render::Image frame;
    if (!getImage(setUp(in), frame))
        return base::Error{base::printable(path) + ": not a frame a bench shard wrote (cut short)"};
    return frame;
}

base::Status writeShardReference(const std::string& path, const Reference& reference) {
    return writeCompressed(path, Content::Reference, [&](QDataStream& out) {
        putImage(out, reference.traced.image);
        putImage(out, reference.traced.noise);
        putMask(out, reference.mirrorMask);
        putMask(out, reference.reflectorMask);
    });
}

base::Result<Reference> readShardReference(const std::string& path, ReferenceKind kind) {
    auto payload = readPayload(path, Content::Reference);
    if (!payload)
        return base::Error{payload.error()};
    QDataStream in(*payload);
    in.skipRawData(12);
    Reference reference;
    reference.kind = kind;
    if (!getImage(setUp(in), reference.traced.image) || !getImage(in, reference.traced.noise) ||
        !getMask(in, reference.mirrorMask) || !getMask(in, reference.reflectorMask))
        return base::Error{base::printable(path) + ": not a reference a bench shard wrote (cut short)"};
    return reference;
}

base::Status compareShardFrames(std::vector<Record>& records,
                                const std::vector<std::filesystem::path>& recordFolder,
                                const std::map<ReferenceKind, std::filesystem::path>& referenceFolder,
                                const std::function<void(const std::string&)>& progress) {
    std::map<ReferenceKind, Reference> references;
    for (const auto& [kind, folder] : referenceFolder) {
        auto reference = readShardReference((folder / shardReferenceFile(kind)).string(), kind);
        if (!reference)
            return base::Error{reference.error()};
        references.emplace(kind, std::move(*reference));
    }
    for (const auto& [family, members] : familyMembers(records)) {
        if (progress)
            progress("comparing the " + familyName(family) + " family's " + std::to_string(members.size()) +
                     " frames");
        std::map<std::size_t, render::Image> frames;
        for (std::size_t i : members) {
            auto frame = readShardFrame((recordFolder[i] / shardFrameFile(records[i].config.id)).string());
            if (!frame)
                return base::Error{frame.error()};
            frames.emplace(i, std::move(*frame));
        }
        auto image = [&](std::size_t i) -> const render::Image& { return frames.at(i); };
        if (base::Status compared = compareFamily(records, members, image, references); !compared)
            return compared;
    }
    return base::Done{};
}

} // namespace speculum::accuracy
