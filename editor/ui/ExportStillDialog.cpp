#include "editor/ui/ExportStillDialog.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/reference/Tracer.hpp"

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
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace speculum::ui {

namespace {

struct Format {
    const char* name;
    const char* suffix;
};
constexpr Format kFormats[] = {{"PNG (8-bit sRGB)", "png"},
                               {"JPEG (8-bit sRGB)", "jpg"},
                               {"TIFF (8-bit sRGB)", "tif"},
                               {"OpenEXR (linear half)", "exr"}};

} // namespace

ExportStillDialog::ExportStillDialog(const QString& suggestedPath, double time, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Export Still"));
    auto* form = new QFormLayout;
    addFileRows(form, suggestedPath);
    addSizeRows(form);
    addTimeRows(form, time);
    addCameraRows(form);
    addReferenceRows(form);

    m_error = new QLabel(this);
    m_error->setStyleSheet(QStringLiteral("color: #b02020;"));
    m_error->setWordWrap(true);
    m_error->hide();

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportStillDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_error);
    layout->addWidget(buttons);
    formatChanged();
    timeChanged();
    referenceChanged();
}

void ExportStillDialog::addFileRows(QFormLayout* form, const QString& suggestedPath) {
    m_path = new QLineEdit(suggestedPath, this);
    m_path->setObjectName(QStringLiteral("stillPath"));
    auto* browse = new QToolButton(this);
    browse->setText(QStringLiteral("…"));
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    form->addRow(tr("File"), pathRow);
    connect(browse, &QToolButton::clicked, this, &ExportStillDialog::browse);

    m_format = new QComboBox(this);
    m_format->setObjectName(QStringLiteral("stillFormat"));
    for (const Format& f : kFormats) {
        m_format->addItem(tr(f.name), QString::fromLatin1(f.suffix));
    }
    selectFormatOf(suggestedPath);
    form->addRow(tr("Format"), m_format);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportStillDialog::formatChanged);
}

void ExportStillDialog::addSizeRows(QFormLayout* form) {
    m_width = new QSpinBox(this);
    m_height = new QSpinBox(this);
    for (QSpinBox* s : {m_width, m_height}) {
        // Larger than the GPU allows in one piece: big stills render in tiles; validateStillExport refuses
        // sizes whose pixels would not fit in memory.
        s->setRange(1, 65536);
        s->setSuffix(tr(" px"));
    }
    m_width->setObjectName(QStringLiteral("stillWidth"));
    m_height->setObjectName(QStringLiteral("stillHeight"));
    m_width->setValue(1280);
    m_height->setValue(720);
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(m_width);
    sizeRow->addWidget(new QLabel(QStringLiteral("×"), this));
    sizeRow->addWidget(m_height);
    form->addRow(tr("Size"), sizeRow);

    m_ssaa = new QSpinBox(this);
    m_ssaa->setObjectName(QStringLiteral("stillSsaa"));
    m_ssaa->setRange(render::kMinSsaa, render::kMaxSsaa);
    m_ssaa->setPrefix(tr("N = "));
    m_ssaa->setToolTip(tr("Supersampling: N×N samples per pixel (the CLI's --ssaa N)"));
    form->addRow(tr("Supersampling"), m_ssaa);
}

// The scene's own start by default, as `speculum render` renders without --time (the clock may be anywhere
// while it plays); the time slider's time is one choice away, and the dialog says which.
void ExportStillDialog::addTimeRows(QFormLayout* form, double time) {
    m_clockTime = time;
    m_timeSource = new QComboBox(this);
    m_timeSource->setObjectName(QStringLiteral("stillTimeSource"));
    m_timeSource->addItem(tr("Scene start"));
    m_timeSource->addItem(tr("Time slider (t = %1 s)").arg(time, 0, 'f', 3));
    m_timeSource->addItem(tr("Other"));
    m_time = new QDoubleSpinBox(this);
    m_time->setObjectName(QStringLiteral("stillTime"));
    m_time->setRange(0.0, 1e6);
    m_time->setDecimals(3);
    m_time->setSuffix(tr(" s"));
    m_time->setValue(0.0);
    m_time->setToolTip(tr("Animation time (the CLI's --time T)"));
    auto* timeRow = new QHBoxLayout;
    timeRow->addWidget(m_timeSource, 1);
    timeRow->addWidget(m_time);
    form->addRow(tr("Time"), timeRow);
    m_timeNote = new QLabel(this);
    m_timeNote->setObjectName(QStringLiteral("stillTimeNote"));
    m_timeNote->setWordWrap(true);
    form->addRow(QString(), m_timeNote);
    connect(m_timeSource, &QComboBox::activated, this, [this](int index) {
        if (index < 2) {
            m_time->setValue(index == 0 ? 0.0 : m_clockTime);
        }
        timeChanged();
    });
    connect(m_time, &QDoubleSpinBox::valueChanged, this, &ExportStillDialog::timeChanged);
}

void ExportStillDialog::addCameraRows(QFormLayout* form) {
    m_camera = new QComboBox(this);
    m_camera->setObjectName(QStringLiteral("stillCamera"));
    m_camera->addItem(tr("Scene camera (as the CLI renders)"));
    m_camera->addItem(tr("Current view"));
    form->addRow(tr("Camera"), m_camera);
}

void ExportStillDialog::addReferenceRows(QFormLayout* form) {
    m_reference = new QCheckBox(tr("Exact reference (ray traced)"), this);
    m_reference->setObjectName(QStringLiteral("stillReference"));
    m_reference->setToolTip(tr("The CPU ray tracer, as `speculum render --reference`: exact mirrors, "
                               "reflections and shadows, for comparing with the raster image. Seconds to "
                               "minutes; the progress dialog can cancel it, and a cancelled export writes "
                               "nothing."));
    form->addRow(QString(), m_reference);
    connect(m_reference, &QCheckBox::toggled, this, &ExportStillDialog::referenceChanged);

    // The tracer's paths per sub-sample that meets a rough surface, as the CLI's --samples: more paths,
    // less noise (the file's metadata gives the noise left).
    m_samples = new QSpinBox(this);
    m_samples->setObjectName(QStringLiteral("stillSamples"));
    m_samples->setRange(render::reference::kMinTraceSamples, render::reference::kMaxTraceSamples);
    m_samples->setValue(scene::StillExportSettings{}.samples);
    m_samples->setSuffix(tr(" paths"));
    m_samples->setToolTip(tr("Paths per sample that meets a rough surface (the CLI's --samples N)"));
    form->addRow(tr("Samples"), m_samples);
}

void ExportStillDialog::referenceChanged() {
    m_samples->setEnabled(m_reference->isChecked());
}

void ExportStillDialog::selectFormatOf(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    for (int i = 0; i < m_format->count(); ++i) {
        if (m_format->itemData(i).toString() == suffix) {
            m_format->setCurrentIndex(i);
        }
    }
}

void ExportStillDialog::timeChanged() {
    const double t = m_time->value();
    const int source = t == 0.0 ? 0 : (t == m_clockTime ? 1 : 2);
    m_timeSource->setCurrentIndex(source);
    const QString at = tr("Renders the scene at t = %1 s").arg(t, 0, 'f', 3);
    m_timeNote->setText(source == 0 ? tr("%1, its start (as `speculum render` without --time); the time "
                                         "slider is at %2 s.")
                                          .arg(at)
                                          .arg(m_clockTime, 0, 'f', 3)
                        : source == 1 ? tr("%1, the time slider's time.").arg(at)
                                      : tr("%1 (the CLI's --time %2).").arg(at).arg(t));
}

QString ExportStillDialog::timeNote() const {
    return m_timeNote->text();
}

void ExportStillDialog::formatChanged() {
    const QString suffix = m_format->currentData().toString();
    QString path = m_path->text();
    const QFileInfo info(path);
    if (!path.isEmpty() && info.suffix().toLower() != suffix) {
        path = info.path() + QLatin1Char('/') + info.completeBaseName() + QLatin1Char('.') + suffix;
        m_path->setText(QDir::cleanPath(path));
    }
}

void ExportStillDialog::browse() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Still"), m_path->text(),
                                                      tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.exr)"));
    if (!path.isEmpty()) {
        m_path->setText(path);
        selectFormatOf(path);
    }
}

QString ExportStillDialog::outputPath() const {
    return m_path->text().trimmed();
}

bool ExportStillDialog::useCurrentView() const {
    return m_camera->currentIndex() == 1;
}

scene::StillExportSettings ExportStillDialog::settings() const {
    scene::StillExportSettings s;
    s.width = m_width->value();
    s.height = m_height->value();
    s.ssaa = m_ssaa->value();
    s.time = m_time->value();
    s.reference = m_reference->isChecked();
    s.samples = m_samples->value();
    return s;
}

void ExportStillDialog::accept() {
    if (auto valid = scene::validateStillExport(settings(), outputPath().toStdString()); !valid) {
        m_error->setText(QString::fromStdString(valid.error()));
        m_error->show();
        return;
    }
    QDialog::accept();
}

} // namespace speculum::ui
