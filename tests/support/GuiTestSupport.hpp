#pragma once

// Helpers shared by the editor's GUI tests: waiting on the event loop, reading pixels.
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/Viewport.hpp"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QThread>
#include <algorithm>
#include <cmath>
#include <functional>

namespace speculum::ui::test {

// Points this process's settings, recovery and cache folders (and those of its children) into `home`.
// Call before the QApplication exists. ctest runs the GUI test programs side by side; with one shared
// settings file, one program's write (an import option, a recent file) would land in another's run.
inline void useTemporaryUserFolders(const QTemporaryDir& home) {
    for (const char* variable : {"XDG_DATA_HOME", "XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"}) {
        qputenv(variable, QFile::encodeName(home.filePath(QString::fromLatin1(variable))));
    }
}

inline bool waitFor(const std::function<bool()>& condition, int timeoutMs = 60000) {
    QElapsedTimer timer;
    timer.start();
    while (!condition()) {
        if (timer.elapsed() > timeoutMs) {
            return false;
        }
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(2);
    }
    return true;
}

// Writes `text` to a file named `name` in `dir` and returns its path; empty when it could not be written.
inline QString writeFileIn(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size())
        return {};
    return path;
}

// Waits until the viewport has drawn at least `frames` more frames than now.
// The scene's model files load on worker threads first (the viewport draws them once they are in).
inline bool waitForFrames(MainWindow& window, int frames = 2) {
    window.viewport().readModels(); // the files the viewport has not drawn yet
    if (!waitFor([&] { return !window.viewport().modelsLoading(); })) {
        return false;
    }
    const int target = window.viewport().framesRendered() + frames;
    return waitFor([&] {
        window.viewport().update(); // paused: the viewport only draws on demand
        return window.viewport().framesRendered() >= target;
    });
}

struct Rgb {
    double r = 0, g = 0, b = 0;
    double distance(const Rgb& o) const {
        return std::max({std::abs(r - o.r), std::abs(g - o.g), std::abs(b - o.b)});
    }
};

// Mean colour of a small square around p (clamped to the image).
inline Rgb patch(const QImage& image, QPoint p, int radius = 3) {
    Rgb sum;
    int n = 0;
    for (int y = p.y() - radius; y <= p.y() + radius; ++y) {
        for (int x = p.x() - radius; x <= p.x() + radius; ++x) {
            if (image.rect().contains(x, y)) {
                const QRgb c = image.pixel(x, y);
                sum.r += qRed(c), sum.g += qGreen(c), sum.b += qBlue(c);
                ++n;
            }
        }
    }
    return n ? Rgb{sum.r / n, sum.g / n, sum.b / n} : Rgb{};
}

// Largest per-channel difference and the mean absolute difference of two same-sized images.
struct ImageDifference {
    int maximum = 255;
    double mean = 255.0;
};

inline ImageDifference compareImages(const QImage& a, const QImage& b) {
    ImageDifference d;
    if (a.size() != b.size() || a.isNull()) {
        return d;
    }
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    long long sum = 0;
    d.maximum = 0;
    for (int row = 0; row < x.height(); ++row) {
        for (int col = 0; col < x.width(); ++col) {
            const QRgb p = x.pixel(col, row), q = y.pixel(col, row);
            const int diffs[3] = {std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                                  std::abs(qBlue(p) - qBlue(q))};
            for (int c : diffs) {
                d.maximum = std::max(d.maximum, c);
                sum += c;
            }
        }
    }
    d.mean = double(sum) / (3.0 * x.width() * x.height());
    return d;
}

} // namespace speculum::ui::test
