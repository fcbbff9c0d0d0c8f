#include "panels/range_guard.h"

#include <QAbstractSpinBox>
#include <QEvent>
#include <QKeyEvent>
#include <QLocale>

#include <optional>

namespace wavelit::editor {
namespace {

QString number(double v) {
    if (v <= -1e29) return QStringLiteral("-∞");
    if (v >= 1e29) return QStringLiteral("∞");
    return QString::number(v, 'g', 6);
}

// The number a spin box's text shows, without its prefix and suffix ("0.5 m", "× 2").
std::optional<double> typedNumber(QString text, const QString& prefix, const QString& suffix) {
    if (!prefix.isEmpty() && text.startsWith(prefix)) text.remove(0, prefix.size());
    if (!suffix.isEmpty() && text.endsWith(suffix)) text.chop(suffix.size());
    text = text.trimmed();
    bool ok = false;
    double value = QLocale().toDouble(text, &ok);
    if (!ok) value = text.toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

class RangeGuard : public QObject {
public:
    RangeGuard(QAbstractSpinBox* spin, const scene::PropertyInfo& info, std::function<void(const QString&)> refuse)
        : QObject(spin), m_spin(spin), m_info(info), m_refuse(std::move(refuse)) {
        spin->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject*, QEvent* event) override {
        const bool commitKey = event->type() == QEvent::KeyPress &&
                               (static_cast<QKeyEvent*>(event)->key() == Qt::Key_Return ||
                                static_cast<QKeyEvent*>(event)->key() == Qt::Key_Enter);
        if (commitKey || event->type() == QEvent::FocusOut) check();
        return false; // the spin box goes on as usual (and reverts an out-of-range text)
    }

private:
    void check() {
        QString prefix, suffix;
        if (auto* d = qobject_cast<QDoubleSpinBox*>(m_spin)) prefix = d->prefix(), suffix = d->suffix();
        if (auto* i = qobject_cast<QSpinBox*>(m_spin)) prefix = i->prefix(), suffix = i->suffix();
        const auto value = typedNumber(m_spin->text(), prefix, suffix);
        if (!value) return;
        if (const QString message = rangeRefusal(m_info, *value); !message.isEmpty() && m_refuse) m_refuse(message);
    }

    QAbstractSpinBox* m_spin;
    scene::PropertyInfo m_info;
    std::function<void(const QString&)> m_refuse;
};

} // namespace

// A number out of range is Intermediate (typing goes on; Enter reverts it after the guard spoke).
QValidator::State TypedDoubleSpinBox::validate(QString& text, int& pos) const {
    const QValidator::State state = QDoubleSpinBox::validate(text, pos);
    if (state == QValidator::Invalid && typedNumber(text, prefix(), suffix())) return QValidator::Intermediate;
    return state;
}

QValidator::State TypedSpinBox::validate(QString& text, int& pos) const {
    const QValidator::State state = QSpinBox::validate(text, pos);
    if (state == QValidator::Invalid && typedNumber(text, prefix(), suffix())) return QValidator::Intermediate;
    return state;
}

QString rangeRefusal(const scene::PropertyInfo& info, double value) {
    if (value >= info.min && value <= info.max) return {};
    QString unit = info.unit.empty() ? QString() : QStringLiteral(" ") + QString::fromStdString(info.unit);
    return QStringLiteral("%1: %2 is outside [%3, %4]%5 — refused, the value stays as it was")
        .arg(QString::fromStdString(info.label), number(value), number(info.min), number(info.max), unit);
}

void guardRange(QAbstractSpinBox* spin, const scene::PropertyInfo& info, std::function<void(const QString&)> refuse) {
    new RangeGuard(spin, info, std::move(refuse));
}

} // namespace wavelit::editor
