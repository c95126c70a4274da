#include "editor/ui/ExportAnimationDialog.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/reference/Tracer.hpp"
#include "render/video/VideoFormat.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace speculum::ui {

namespace {

struct Format {
    const char* name;
    const char* suffix;
    std::optional<render::video::VideoFormat> video; // none: an image sequence
};
const Format kFormats[] = {{"MP4 (H.264)", "mp4", render::video::VideoFormat::Mp4},
                           {"WebM (VP9)", "webm", render::video::VideoFormat::WebM},
                           {"GIF (animated)", "gif", render::video::VideoFormat::Gif},
                           {"PNG sequence (one file a frame)", "png", std::nullopt}};
constexpr int kSequenceFormat = 3;

constexpr int kCameraScene = 0, kCameraView = 1;
constexpr int kRendererRaster = 0, kRendererExact = 1;

const QString kSettingsGroup = QStringLiteral("exportAnimation");

// A sequence's frame number in a file name, with the underscore the dialog puts before it.
const QRegularExpression& frameNumberInName() {
    static const QRegularExpression number(QStringLiteral("_?%(0[1-9])?d"));
    return number;
}

// `path` written as `format` wants it: a clip without a frame number, a sequence with one.
QString pathForFormat(const QString& path, const Format& format) {
    const QFileInfo info(path);
    QString stem = info.completeBaseName();
    if (format.video) {
        stem.remove(frameNumberInName());
    } else if (!stem.contains(frameNumberInName())) {
        stem += QStringLiteral("_%04d");
    }
    return QDir::cleanPath(info.path() + QLatin1Char('/') + stem + QLatin1Char('.') +
                           QString::fromLatin1(format.suffix));
}

int framesIn(double seconds, int fps) {
    return std::max(1, int(std::lround(seconds * fps)));
}

} // namespace

ExportAnimationDialog::ExportAnimationDialog(const QString& suggestedBase, double loopSeconds, QSize viewSize,
                                             QWidget* parent)
    : QDialog(parent)
    , m_loopSeconds(loopSeconds) {
    setWindowTitle(tr("Export Animation"));
    auto* form = new QFormLayout;
    addFileRows(form, suggestedBase);
    addFrameRows(form);
    addTurntableRows(form);
    addSizeRows(form, viewSize);
    addRendererRows(form);

    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("animError"));
    m_error->setStyleSheet(QStringLiteral("color: #b02020;"));
    m_error->setWordWrap(true);
    m_error->hide();

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportAnimationDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_error);
    layout->addWidget(buttons);
    restoreChoices();
    formatChanged();
    turntableChanged();
    rendererChanged();
}

void ExportAnimationDialog::addFileRows(QFormLayout* form, const QString& suggestedBase) {
    m_path = new QLineEdit(suggestedBase + QStringLiteral(".mp4"), this);
    m_path->setObjectName(QStringLiteral("animPath"));
    auto* browse = new QToolButton(this);
    browse->setText(QStringLiteral("…"));
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    form->addRow(tr("File"), pathRow);
    connect(browse, &QToolButton::clicked, this, &ExportAnimationDialog::browse);
    connect(m_path, &QLineEdit::textEdited, this, &ExportAnimationDialog::selectFormatOf);

    m_format = new QComboBox(this);
    m_format->setObjectName(QStringLiteral("animFormat"));
    const std::vector<render::video::VideoFormat> available = render::video::availableVideoFormats();
    auto* items = qobject_cast<QStandardItemModel*>(m_format->model());
    for (const Format& f : kFormats) {
        m_format->addItem(tr(f.name), QString::fromLatin1(f.suffix));
        if (f.video && std::find(available.begin(), available.end(), *f.video) == available.end()) {
            QStandardItem* item = items->item(m_format->count() - 1);
            item->setEnabled(false);
            item->setToolTip(tr("This machine's FFmpeg has no %1 encoder")
                                 .arg(QString::fromStdString(render::video::codecName(*f.video))));
        }
    }
    form->addRow(tr("Format"), m_format);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportAnimationDialog::formatChanged);
}

void ExportAnimationDialog::addFrameRows(QFormLayout* form) {
    m_first = new QSpinBox(this);
    m_last = new QSpinBox(this);
    for (QSpinBox* s : {m_first, m_last}) {
        s->setRange(0, scene::kMaxFrameNumber);
    }
    m_first->setObjectName(QStringLiteral("animFirst"));
    m_last->setObjectName(QStringLiteral("animLast"));
    m_first->setToolTip(tr("Frame N shows the scene at N / fps seconds (the CLI's --frames A..B)"));
    auto* rangeRow = new QHBoxLayout;
    rangeRow->addWidget(m_first);
    rangeRow->addWidget(new QLabel(tr("to"), this));
    rangeRow->addWidget(m_last);
    form->addRow(tr("Frames"), rangeRow);

    m_fps = new QSpinBox(this);
    m_fps->setObjectName(QStringLiteral("animFps"));
    m_fps->setRange(render::video::kMinFps, render::video::kMaxFps);
    m_fps->setValue(24);
    m_fps->setSuffix(tr(" fps"));
    form->addRow(tr("Frame rate"), m_fps);

    m_framesNote = new QLabel(this);
    m_framesNote->setObjectName(QStringLiteral("animFramesNote"));
    m_framesNote->setWordWrap(true);
    form->addRow(QString(), m_framesNote);
    m_settingRange = true;
    m_last->setValue(framesIn(m_loopSeconds, m_fps->value()) - 1);
    m_settingRange = false;
    connect(m_first, &QSpinBox::valueChanged, this, &ExportAnimationDialog::rangeEdited);
    connect(m_last, &QSpinBox::valueChanged, this, &ExportAnimationDialog::rangeEdited);
    connect(m_fps, &QSpinBox::valueChanged, this, &ExportAnimationDialog::fpsChanged);
}

void ExportAnimationDialog::addTurntableRows(QFormLayout* form) {
    m_turntable = new QCheckBox(tr("Turntable: the camera orbits its target once in"), this);
    m_turntable->setObjectName(QStringLiteral("animTurntable"));
    m_turntable->setToolTip(tr("The CLI's --turntable SECONDS; sets the frames to one turn, so the clip "
                               "loops without a seam"));
    m_turnSeconds = new QDoubleSpinBox(this);
    m_turnSeconds->setObjectName(QStringLiteral("animTurnSeconds"));
    m_turnSeconds->setRange(0.1, 3600.0);
    m_turnSeconds->setDecimals(2);
    m_turnSeconds->setSuffix(tr(" s"));
    m_turnSeconds->setValue(std::clamp(m_loopSeconds, 0.1, 3600.0));
    auto* row = new QHBoxLayout;
    row->addWidget(m_turntable);
    row->addWidget(m_turnSeconds);
    row->addStretch(1);
    form->addRow(tr("Camera path"), row);
    connect(m_turntable, &QCheckBox::toggled, this, &ExportAnimationDialog::turntableChanged);
    connect(m_turnSeconds, &QDoubleSpinBox::valueChanged, this, &ExportAnimationDialog::turntableChanged);
}

void ExportAnimationDialog::addSizeRows(QFormLayout* form, QSize viewSize) {
    m_width = new QSpinBox(this);
    m_height = new QSpinBox(this);
    for (QSpinBox* s : {m_width, m_height}) {
        s->setRange(2, 16384);
        s->setSuffix(tr(" px"));
    }
    m_width->setObjectName(QStringLiteral("animWidth"));
    m_height->setObjectName(QStringLiteral("animHeight"));
    // H.264 and VP9 take even sizes only: the viewport's, rounded down to one.
    const bool useView = viewSize.width() >= 2 && viewSize.height() >= 2;
    m_width->setValue(useView ? viewSize.width() & ~1 : 1280);
    m_height->setValue(useView ? viewSize.height() & ~1 : 720);
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(m_width);
    sizeRow->addWidget(new QLabel(QStringLiteral("×"), this));
    sizeRow->addWidget(m_height);
    form->addRow(tr("Size"), sizeRow);

    m_ssaa = new QSpinBox(this);
    m_ssaa->setObjectName(QStringLiteral("animSsaa"));
    m_ssaa->setRange(render::kMinSsaa, render::kMaxSsaa);
    m_ssaa->setPrefix(tr("N = "));
    m_ssaa->setToolTip(tr("Supersampling: N×N samples per pixel (the CLI's --ssaa N)"));
    form->addRow(tr("Supersampling"), m_ssaa);
}

void ExportAnimationDialog::addRendererRows(QFormLayout* form) {
    m_renderer = new QComboBox(this);
    m_renderer->setObjectName(QStringLiteral("animRenderer"));
    m_renderer->addItem(tr("Raster (the GPU, as the viewport draws)"));
    m_renderer->addItem(tr("Exact reference (ray traced on the CPU)"));
    m_renderer->setToolTip(tr("The exact reference is `speculum render --reference`: exact mirrors, "
                              "reflections and shadows; seconds to minutes a frame"));
    form->addRow(tr("Renderer"), m_renderer);
    connect(m_renderer, &QComboBox::currentIndexChanged, this, &ExportAnimationDialog::rendererChanged);

    m_samples = new QSpinBox(this);
    m_samples->setObjectName(QStringLiteral("animSamples"));
    m_samples->setRange(render::reference::kMinTraceSamples, render::reference::kMaxTraceSamples);
    m_samples->setValue(scene::StillExportSettings{}.samples);
    m_samples->setSuffix(tr(" paths"));
    m_samples->setToolTip(tr("Paths per sample that meets a rough surface (the CLI's --samples N)"));
    form->addRow(tr("Samples"), m_samples);

    m_camera = new QComboBox(this);
    m_camera->setObjectName(QStringLiteral("animCamera"));
    m_camera->addItem(tr("Scene camera (as the CLI renders)"));
    m_camera->addItem(tr("Current view"));
    form->addRow(tr("Camera"), m_camera);
}

// The last export's choices; the file and the frames are this scene's own.
void ExportAnimationDialog::restoreChoices() {
    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    const QString suffix = settings.value(QStringLiteral("format")).toString();
    const int format = m_format->findData(suffix);
    if (format >= 0 && (m_format->model()->flags(m_format->model()->index(format, 0)) & Qt::ItemIsEnabled)) {
        m_format->setCurrentIndex(format);
    }
    m_fps->setValue(settings.value(QStringLiteral("fps"), m_fps->value()).toInt());
    m_width->setValue(settings.value(QStringLiteral("width"), m_width->value()).toInt());
    m_height->setValue(settings.value(QStringLiteral("height"), m_height->value()).toInt());
    m_ssaa->setValue(settings.value(QStringLiteral("ssaa"), m_ssaa->value()).toInt());
    const bool exact = settings.value(QStringLiteral("exact"), false).toBool();
    m_renderer->setCurrentIndex(exact ? kRendererExact : kRendererRaster);
    m_samples->setValue(settings.value(QStringLiteral("samples"), m_samples->value()).toInt());
    const bool view = settings.value(QStringLiteral("currentView"), false).toBool();
    m_camera->setCurrentIndex(view ? kCameraView : kCameraScene);
    m_turnSeconds->setValue(
        settings.value(QStringLiteral("turntableSeconds"), m_turnSeconds->value()).toDouble());
    m_turntable->setChecked(settings.value(QStringLiteral("turntable"), false).toBool());
}

void ExportAnimationDialog::rememberChoices() const {
    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    settings.setValue(QStringLiteral("format"), m_format->currentData());
    settings.setValue(QStringLiteral("fps"), m_fps->value());
    settings.setValue(QStringLiteral("width"), m_width->value());
    settings.setValue(QStringLiteral("height"), m_height->value());
    settings.setValue(QStringLiteral("ssaa"), m_ssaa->value());
    settings.setValue(QStringLiteral("exact"), m_renderer->currentIndex() == kRendererExact);
    settings.setValue(QStringLiteral("samples"), m_samples->value());
    settings.setValue(QStringLiteral("currentView"), useCurrentView());
    settings.setValue(QStringLiteral("turntable"), m_turntable->isChecked());
    settings.setValue(QStringLiteral("turntableSeconds"), m_turnSeconds->value());
}

// The combo follows the file name as it is typed or picked; the name is left as written (a sequence may
// be .exr or .tif as well).
void ExportAnimationDialog::selectFormatOf(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    const bool numbered = QFileInfo(path).fileName().contains(frameNumberInName());
    const int index = numbered ? kSequenceFormat : m_format->findData(suffix);
    if (index >= 0) {
        const QSignalBlocker keepName(m_format);
        m_format->setCurrentIndex(index);
    }
}

void ExportAnimationDialog::formatChanged() {
    const Format& format = kFormats[std::max(0, m_format->currentIndex())];
    const QString path = m_path->text().trimmed();
    const bool numbered = QFileInfo(path).fileName().contains(frameNumberInName());
    const bool fits = format.video ? QFileInfo(path).suffix().toLower() == QLatin1String(format.suffix)
                                   : numbered && !render::video::videoFormatOf(path.toStdString());
    if (!path.isEmpty() && !fits) {
        m_path->setText(pathForFormat(path, format));
    }
}

void ExportAnimationDialog::browse() {
    QString path = QFileDialog::getSaveFileName(this, tr("Export Animation"), m_path->text(),
                                                tr("Clips (*.mp4 *.webm *.gif);;Image sequence (*.png)"));
    if (path.isEmpty()) {
        return;
    }
    // A picked image without a frame number becomes the sequence's pattern.
    if (!render::video::videoFormatOf(path.toStdString()) &&
        !QFileInfo(path).fileName().contains(QLatin1Char('%'))) {
        path = pathForFormat(path, kFormats[kSequenceFormat]);
    }
    m_path->setText(path);
    selectFormatOf(path);
}

void ExportAnimationDialog::setFrameCount(int count) {
    m_settingRange = true;
    m_last->setValue(std::min(scene::kMaxFrameNumber, m_first->value() + count - 1));
    m_settingRange = false;
}

void ExportAnimationDialog::fpsChanged() {
    if (m_turntable->isChecked()) {
        setFrameCount(framesIn(m_turnSeconds->value(), m_fps->value()));
    } else if (m_rangeFollowsLoop) {
        setFrameCount(framesIn(m_loopSeconds, m_fps->value()));
    }
    updateFramesNote();
}

void ExportAnimationDialog::rangeEdited() {
    if (!m_settingRange) {
        m_rangeFollowsLoop = false;
    }
    updateFramesNote();
}

void ExportAnimationDialog::turntableChanged() {
    m_turnSeconds->setEnabled(m_turntable->isChecked());
    fpsChanged();
}

void ExportAnimationDialog::updateFramesNote() {
    m_framesNote->setText(framesNote());
}

QString ExportAnimationDialog::framesNote() const {
    const int count = m_last->value() - m_first->value() + 1;
    if (count < 1) {
        return tr("No frames: the last is before the first.");
    }
    const int fps = m_fps->value();
    const QString length = (count == 1 ? tr("1 frame") : tr("%1 frames").arg(count)) +
                           tr(", %1 s at %2 fps").arg(double(count) / fps, 0, 'f', 3).arg(fps);
    if (m_turntable->isChecked() && count == framesIn(m_turnSeconds->value(), fps)) {
        return tr("%1: one turn of the camera.").arg(length);
    }
    if (m_first->value() == 0 && count == framesIn(m_loopSeconds, fps)) {
        return tr("%1: one loop of the scene's animation.").arg(length);
    }
    return length + QLatin1Char('.');
}

void ExportAnimationDialog::rendererChanged() {
    m_samples->setEnabled(m_renderer->currentIndex() == kRendererExact);
}

QString ExportAnimationDialog::outputPath() const {
    return m_path->text().trimmed();
}

bool ExportAnimationDialog::useCurrentView() const {
    return m_camera->currentIndex() == kCameraView;
}

scene::AnimationSettings ExportAnimationDialog::settings() const {
    scene::AnimationSettings s;
    s.still.width = m_width->value();
    s.still.height = m_height->value();
    s.still.ssaa = m_ssaa->value();
    s.still.reference = m_renderer->currentIndex() == kRendererExact;
    s.still.samples = m_samples->value();
    s.frames = {m_first->value(), m_last->value()};
    s.fps = m_fps->value();
    if (m_turntable->isChecked()) {
        s.turntableSeconds = m_turnSeconds->value();
    }
    return s;
}

void ExportAnimationDialog::accept() {
    auto output = scene::parseAnimationOutput(outputPath().toStdString());
    base::Status valid = output ? scene::validateAnimationExport(settings(), *output)
                                : base::Status(base::Error{output.error()});
    if (!valid) {
        m_error->setText(QString::fromStdString(valid.error()));
        m_error->show();
        return;
    }
    selectFormatOf(outputPath()); // what is remembered is the format written, whatever the combo said
    rememberChoices();
    QDialog::accept();
}

} // namespace speculum::ui
