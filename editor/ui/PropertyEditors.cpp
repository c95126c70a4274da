#include "editor/ui/PropertyEditors.hpp"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QStyleOptionSpinBox>
#include <QToolButton>
#include <QWheelEvent>
#include <cmath>
#include <limits>
#include <optional>

namespace speculum::ui {

using document::PropertyInfo;
using document::PropertyKind;

namespace {

constexpr double kWide = 1e12; // spin boxes take anything; validation decides
constexpr int kSliderSteps = 1000;

// Stored precision of every number field: QDoubleSpinBox rounds each value to decimals(), so with the 3
// shown decimals an FBX scale of 5e-5 became 0 (shown as 0.000, every edit refused as a zero scale).
constexpr int kStoredDecimals = 15;

// A spin box that keeps the full value and shows it with the precision it needs: `shown` decimals when they
// carry the value to a part in a thousand, else the shortest scientific form ("5e-05"). Typing accepts
// either form.
class NumberSpin : public QDoubleSpinBox {
public:
    NumberSpin(int shownDecimals, QWidget* parent)
        : QDoubleSpinBox(parent)
        , m_shown(shownDecimals) {
        m_locale.setNumberOptions(QLocale::OmitGroupSeparator);
        setDecimals(kStoredDecimals);
    }

    QString textFromValue(double value) const override { return fieldText(value, m_shown, m_locale); }

    double valueFromText(const QString& text) const override { return parse(text).value_or(value()); }

    QValidator::State validate(QString& input, int&) const override {
        const QString bare = stripped(input);
        // What a number looks like while it is being typed: "-", ".", "-.", "5e", "5e-".
        QString start = bare;
        if (start.startsWith(QLatin1Char('-')) || start.startsWith(QLatin1Char('+'))) {
            start.remove(0, 1);
        }
        if (start.isEmpty() || start == m_locale.decimalPoint() || start == QLatin1String(".") ||
            bare.endsWith(QLatin1Char('e'), Qt::CaseInsensitive) ||
            bare.endsWith(QLatin1String("e-"), Qt::CaseInsensitive) ||
            bare.endsWith(QLatin1String("e+"), Qt::CaseInsensitive)) {
            return QValidator::Intermediate;
        }
        return parse(input) ? QValidator::Acceptable : QValidator::Invalid;
    }

    void fixup(QString&) const override {}

    // Wide enough to show a value of the sizes scenes hold ("-0000.000", at the decimals shown) with the
    // prefix and unit. Qt's own hints measure the range's ends, and the range here is ±1e12 (the
    // property's validation decides, not the spin box), which would ask for the width of 22 digits; a
    // spin box's size policy makes its size hint its least width, so both say the same.
    QSize sizeHint() const override { return minimumSizeHint(); }
    QSize minimumSizeHint() const override {
        ensurePolished();
        const QString sample = QStringLiteral("-0000") + (m_shown > 0 ? QStringLiteral(".") : QString()) +
                               QString(m_shown, QLatin1Char('0'));
        const int text = fontMetrics().horizontalAdvance(prefix() + sample + suffix()) + 2; // + the cursor
        QStyleOptionSpinBox option;
        initStyleOption(&option);
        const int height = QDoubleSpinBox::minimumSizeHint().height();
        const QSize withFrame =
            style()->sizeFromContents(QStyle::CT_SpinBox, &option, QSize(text, height), this);
        return {withFrame.width(), height};
    }

    static QString fieldText(double value, int shown, const QLocale& locale) {
        const QString fixed = locale.toString(value, 'f', shown);
        const double back = locale.toDouble(fixed);
        if (value == 0.0 || std::abs(back - value) <= 1e-3 * std::abs(value)) {
            return fixed;
        }
        return locale.toString(value, 'g', 4);
    }

private:
    QString stripped(const QString& text) const {
        QString t = text;
        if (!prefix().isEmpty() && t.startsWith(prefix())) {
            t.remove(0, prefix().size());
        }
        if (!suffix().isEmpty() && t.endsWith(suffix())) {
            t.chop(suffix().size());
        }
        return t.trimmed();
    }

    std::optional<double> parse(const QString& text) const {
        const QString bare = stripped(text);
        bool ok = false;
        double v = m_locale.toDouble(bare, &ok);
        if (!ok) {
            v = bare.toDouble(&ok); // "5e-5" typed in a locale with a decimal comma
        }
        if (!ok || !std::isfinite(v) || v < minimum() || v > maximum()) {
            return std::nullopt;
        }
        return v;
    }

    int m_shown;
    QLocale m_locale;
};

QDoubleSpinBox* makeSpin(const PropertyInfo& info, QWidget* parent, const QString& name) {
    auto* spin = new NumberSpin(info.kind == PropertyKind::Integer ? 0 : std::max(info.decimals, 3), parent);
    spin->setObjectName(name);
    spin->setRange(-kWide, kWide);
    spin->setSingleStep(info.step);
    spin->setKeyboardTracking(false); // typing commits on Enter or focus-out, not per keystroke
    spin->setAccelerated(true);
    spin->setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
    if (!info.unit.isEmpty()) {
        spin->setSuffix(info.unit);
    }
    spin->setToolTip(info.tooltip);
    spin->setFocusPolicy(Qt::StrongFocus);
    return spin;
}

double srgbFromLinear(double c) {
    c = std::clamp(c, 0.0, 1.0); // only for the swatch's display colour
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

double linearFromSrgb(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

class NumberEditor : public PropertyEditor {
public:
    NumberEditor(const PropertyInfo& info, QWidget* parent)
        : PropertyEditor(info, parent) {
        auto* layout = new QHBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        if (info.slider) {
            m_slider = new QSlider(Qt::Horizontal, this);
            m_slider->setObjectName(info.key + QStringLiteral(".slider"));
            m_slider->setRange(0, kSliderSteps);
            m_slider->setToolTip(info.tooltip);
            m_slider->setFocusPolicy(Qt::StrongFocus);
            guardWheel(m_slider);
            layout->addWidget(m_slider, 1);
            // A drag is one gesture: it begins on press and ends on release, so the next edit is a new step.
            connect(m_slider, &QSlider::sliderPressed, this, &PropertyEditor::interactionStarted);
            connect(m_slider, &QSlider::sliderReleased, this, &PropertyEditor::interactionStarted);
            connect(m_slider, &QSlider::valueChanged, this, [this](int v) {
                const double value =
                    m_info.softMinimum + (m_info.softMaximum - m_info.softMinimum) * v / kSliderSteps;
                const double rounded = m_info.kind == PropertyKind::Integer ? std::round(value) : value;
                {
                    QSignalBlocker block(m_spin);
                    m_spin->setValue(rounded);
                }
                emit edited(m_info.kind == PropertyKind::Integer ? QVariant(int(rounded))
                                                                 : QVariant(rounded));
            });
        }
        m_spin = makeSpin(info, this, info.key);
        layout->addWidget(m_spin, info.slider ? 0 : 1);
        watchFocus(m_spin);
        // Held arrows merge into one step; each typed value (Enter) is a step of its own.
        connect(m_spin, &QDoubleSpinBox::editingFinished, this, &PropertyEditor::interactionStarted);
        connect(m_spin, &QDoubleSpinBox::valueChanged, this, [this](double v) {
            syncSlider(v);
            emit edited(m_info.kind == PropertyKind::Integer ? QVariant(int(std::round(v))) : QVariant(v));
        });
    }

    void setValue(const QVariant& value) override {
        const double v = value.toDouble();
        QSignalBlocker block(m_spin);
        m_spin->setValue(v);
        syncSlider(v);
    }

private:
    void syncSlider(double v) {
        if (!m_slider || m_slider->isSliderDown()) {
            return;
        }
        const double span = m_info.softMaximum - m_info.softMinimum;
        const double f = span > 0 ? (v - m_info.softMinimum) / span : 0.0;
        QSignalBlocker block(m_slider);
        m_slider->setValue(int(std::lround(std::clamp(f, 0.0, 1.0) * kSliderSteps)));
    }

    QDoubleSpinBox* m_spin = nullptr;
    QSlider* m_slider = nullptr;
};

class VectorEditor : public PropertyEditor {
public:
    VectorEditor(const PropertyInfo& info, int n, QWidget* parent)
        : PropertyEditor(info, parent) {
        auto* layout = new QHBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(2);
        const bool color = info.kind == PropertyKind::Color;
        if (color) {
            m_swatch = new QPushButton(this);
            m_swatch->setObjectName(info.key + QStringLiteral(".swatch"));
            m_swatch->setFixedSize(28, 22);
            m_swatch->setToolTip(tr("Pick a colour"));
            layout->addWidget(m_swatch);
            connect(m_swatch, &QPushButton::clicked, this, &VectorEditor::pickColor);
        }
        static const char* const xyz[] = {"x", "y", "z"};
        static const char* const rgb[] = {"r", "g", "b"};
        for (int i = 0; i < n; ++i) {
            auto* spin =
                makeSpin(info, this, info.key + QLatin1Char('.') + QLatin1String(color ? rgb[i] : xyz[i]));
            spin->setSuffix(QString());
            spin->setPrefix(QString::fromLatin1(color ? rgb[i] : xyz[i]).toUpper() + QLatin1Char(' '));
            spin->setToolTip(info.tooltip.isEmpty() ? info.unit.trimmed() : info.tooltip);
            layout->addWidget(spin, 1);
            watchFocus(spin);
            connect(spin, &QDoubleSpinBox::valueChanged, this, [this] {
                updateSwatch();
                emit edited(value());
            });
            m_spins.push_back(spin);
        }
    }

    void setValue(const QVariant& v) override {
        const QVariantList list = v.toList();
        for (int i = 0; i < m_spins.size() && i < list.size(); ++i) {
            QSignalBlocker block(m_spins[i]);
            m_spins[i]->setValue(list[i].toDouble());
        }
        updateSwatch();
    }

private:
    QVariant value() const {
        QVariantList list;
        for (auto* spin : m_spins) {
            list << spin->value();
        }
        return list;
    }

    QColor displayColor() const {
        if (m_spins.size() < 3) {
            return {};
        }
        return QColor::fromRgbF(float(srgbFromLinear(m_spins[0]->value())),
                                float(srgbFromLinear(m_spins[1]->value())),
                                float(srgbFromLinear(m_spins[2]->value())));
    }

    void updateSwatch() {
        if (m_swatch) {
            m_swatch->setStyleSheet(
                QStringLiteral("background-color: %1; border: 1px solid #444;").arg(displayColor().name()));
        }
    }

    void pickColor() {
        emit interactionStarted();
        const QVariant before = value();
        QColorDialog dialog(displayColor(), this);
        dialog.setWindowTitle(tr("%1").arg(m_info.label));
        dialog.setOption(QColorDialog::DontUseNativeDialog);
        // Live preview: every change while the dialog is open is one gesture (one undo step).
        connect(&dialog, &QColorDialog::currentColorChanged, this,
                [this](const QColor& c) { applyColor(c); });
        if (dialog.exec() == QDialog::Accepted) {
            applyColor(dialog.selectedColor());
        } else {
            setValue(before);
            emit edited(before);
        }
    }

    void applyColor(const QColor& c) {
        const double values[] = {linearFromSrgb(c.redF()), linearFromSrgb(c.greenF()),
                                 linearFromSrgb(c.blueF())};
        for (int i = 0; i < 3; ++i) {
            QSignalBlocker block(m_spins[i]);
            m_spins[i]->setValue(values[i]);
        }
        updateSwatch();
        emit edited(value());
    }

    QList<QDoubleSpinBox*> m_spins;
    QPushButton* m_swatch = nullptr;
};

class BoolEditor : public PropertyEditor {
public:
    BoolEditor(const PropertyInfo& info, QWidget* parent)
        : PropertyEditor(info, parent) {
        auto* layout = new QHBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        m_box = new QCheckBox(this);
        m_box->setObjectName(info.key);
        m_box->setToolTip(info.tooltip);
        layout->addWidget(m_box);
        connect(m_box, &QCheckBox::toggled, this, [this](bool on) {
            emit interactionStarted();
            emit edited(on);
        });
    }
    void setValue(const QVariant& v) override {
        QSignalBlocker block(m_box);
        m_box->setChecked(v.toBool());
    }

private:
    QCheckBox* m_box;
};

class EnumEditor : public PropertyEditor {
public:
    EnumEditor(const PropertyInfo& info, QWidget* parent)
        : PropertyEditor(info, parent) {
        auto* layout = new QHBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        m_combo = new QComboBox(this);
        m_combo->setObjectName(info.key);
        m_combo->addItems(info.options);
        // The panel is as wide as its widest row (Inspector::fitToContent): an option naming a node of an
        // imported model must not widen it, so the combo asks for a few words and shows the rest as room
        // allows (the list that drops down is as wide as its items).
        m_combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        m_combo->setMinimumContentsLength(14);
        m_combo->setToolTip(info.tooltip);
        m_combo->setFocusPolicy(Qt::StrongFocus); // WheelFocus would let a passing wheel focus and edit it
        guardWheel(m_combo);
        layout->addWidget(m_combo, 1);
        connect(m_combo, &QComboBox::activated, this, [this](int i) {
            emit interactionStarted();
            emit edited(i);
        });
    }
    void setValue(const QVariant& v) override {
        QSignalBlocker block(m_combo);
        m_combo->setCurrentIndex(v.isValid() ? v.toInt() : -1);
    }

private:
    QComboBox* m_combo;
};

class TextEditor : public PropertyEditor {
public:
    TextEditor(const PropertyInfo& info, QWidget* parent)
        : PropertyEditor(info, parent) {
        auto* layout = new QHBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        m_edit = new QLineEdit(this);
        m_edit->setObjectName(info.key);
        m_edit->setToolTip(info.tooltip);
        layout->addWidget(m_edit, 1);
        connect(m_edit, &QLineEdit::editingFinished, this, [this] {
            if (m_edit->isModified()) {
                m_edit->setModified(false);
                emit interactionStarted();
                emit edited(m_edit->text());
            }
        });
        if (info.kind == PropertyKind::FilePath) {
            auto* browse = new QToolButton(this);
            browse->setObjectName(info.key + QStringLiteral(".browse"));
            browse->setText(QStringLiteral("…"));
            browse->setToolTip(tr("Choose a file"));
            layout->addWidget(browse);
            connect(browse, &QToolButton::clicked, this, [this] {
                const QString start =
                    m_edit->text().isEmpty() ? QString() : QFileInfo(m_edit->text()).absolutePath();
                const QString path =
                    QFileDialog::getOpenFileName(this, m_info.label, start, m_info.fileFilter);
                if (!path.isEmpty()) {
                    m_edit->setText(path);
                    emit interactionStarted();
                    emit edited(path);
                }
            });
            m_edit->setPlaceholderText(tr("none"));
        }
    }
    void setValue(const QVariant& v) override {
        QSignalBlocker block(m_edit);
        m_edit->setText(v.toString());
        m_edit->setModified(false);
        m_edit->setCursorPosition(0);
    }

private:
    QLineEdit* m_edit;
};

} // namespace

PropertyEditor::PropertyEditor(const PropertyInfo& info, QWidget* parent)
    : QWidget(parent)
    , m_info(info) {
    setObjectName(info.key + QStringLiteral(".editor"));
}

PropertyEditor* PropertyEditor::create(const PropertyInfo& info, QWidget* parent) {
    switch (info.kind) {
    case PropertyKind::Number:
    case PropertyKind::Integer:
        return new NumberEditor(info, parent);
    case PropertyKind::Vector2:
        return new VectorEditor(info, 2, parent);
    case PropertyKind::Vector3:
    case PropertyKind::Color:
        return new VectorEditor(info, 3, parent);
    case PropertyKind::Bool:
        return new BoolEditor(info, parent);
    case PropertyKind::Enum:
        return new EnumEditor(info, parent);
    case PropertyKind::Text:
    case PropertyKind::FilePath:
        return new TextEditor(info, parent);
    }
    return nullptr;
}

void PropertyEditor::setInvalid(bool invalid) {
    setStyleSheet(invalid ? QStringLiteral("QAbstractSpinBox, QLineEdit { border: 2px solid #d03030; }")
                          : QString());
}

void PropertyEditor::watchFocus(QWidget* widget) {
    widget->installEventFilter(this); // also guards the wheel
}

void PropertyEditor::guardWheel(QWidget* widget) {
    widget->installEventFilter(this);
}

bool PropertyEditor::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::FocusIn) {
        emit interactionStarted();
    }
    // A wheel merely passing over a field must not edit it (an undo step nobody asked for): without focus
    // the event is withheld from the field and, ignored, travels on to the Properties panel, which scrolls.
    if (event->type() == QEvent::Wheel) {
        if (auto* widget = qobject_cast<QWidget*>(watched); widget && !widget->hasFocus()) {
            event->ignore();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

QString PropertyEditor::numberText(double value, int decimals) {
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return NumberSpin::fieldText(value, decimals, locale);
}

} // namespace speculum::ui
