#include "scripting/script_api.h"

#include "app/autosave_controller.h"
#include "app/editor_actions.h"
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "app/unsaved_changes_prompt.h"
#include "panels/entity_ref.h"
#include "panels/outline_panel.h"
#include "viewport/render_controller.h"
#include "viewport/viewport_widget.h"

#include "scene/image_io.h"

#include <QAction>
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QEventLoop>
#include <QJSEngine>
#include <QTimer>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>

#include <cmath>
#include <optional>

namespace wavelit::editor {
namespace {

// Spins the UI event loop until done() or the deadline; true when done() became true.
template <typename Done> bool waitUntil(Done done, QDeadlineTimer deadline) {
    while (!done()) {
        if (deadline.hasExpired()) return false;
        QEventLoop loop;
        QTimer::singleShot(20, &loop, &QEventLoop::quit);
        loop.exec(QEventLoop::AllEvents);
    }
    return true;
}

std::optional<scene::PropertyValue> toPropertyValue(const scene::Scene& scene,
                                                    const scene::PropertyInfo& info,
                                                    const QJSValue& v) {
    auto vec = [&](int n) -> std::optional<glm::vec3> {
        if (!v.isArray() || v.property("length").toInt() != n) return std::nullopt;
        glm::vec3 out(0.0f);
        for (int i = 0; i < n; ++i) {
            const QJSValue c = v.property(quint32(i));
            if (!c.isNumber()) return std::nullopt;
            out[i] = float(c.toNumber());
        }
        return out;
    };
    switch (info.type) {
    case scene::PropertyType::Bool:
        if (v.isBool()) return v.toBool();
        break;
    case scene::PropertyType::Int:
        if (v.isNumber() && std::floor(v.toNumber()) == v.toNumber()) return v.toInt();
        break;
    case scene::PropertyType::Float:
        if (v.isNumber()) return float(v.toNumber());
        break;
    case scene::PropertyType::Vec2:
        if (auto c = vec(2)) return glm::vec2(c->x, c->y);
        break;
    case scene::PropertyType::Vec3:
    case scene::PropertyType::Color:
        if (auto c = vec(3)) return *c;
        break;
    case scene::PropertyType::String:
    case scene::PropertyType::Enum:
    case scene::PropertyType::Path:
        if (v.isString()) return v.toString().toStdString();
        break;
    case scene::PropertyType::IdRef:
        if (v.isString()) {
            // The kind is known: a plain name is never ambiguous here; "kind:name" works too.
            std::string name = v.toString().toStdString();
            const std::string prefix = std::string(scene::entityKindName(info.refersTo)) + ":";
            if (name.rfind(prefix, 0) == 0) name = name.substr(prefix.size());
            if (auto ref = findEntityOfKind(scene, info.refersTo, name)) return ref->id;
        } else if (v.isNumber()) {
            return scene::EntityId(v.toNumber());
        }
        break;
    }
    return std::nullopt;
}

QJSValue toJsValue(QJSEngine* engine, const scene::Scene& scene, const scene::PropertyInfo& info,
                   const scene::PropertyValue& value) {
    return std::visit(
        [&](const auto& x) -> QJSValue {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, bool>) return QJSValue(x);
            else if constexpr (std::is_same_v<T, int>) return QJSValue(x);
            else if constexpr (std::is_same_v<T, float>) return QJSValue(double(x));
            else if constexpr (std::is_same_v<T, std::string>) return QJSValue(QString::fromStdString(x));
            else if constexpr (std::is_same_v<T, scene::EntityId>)
                return QJSValue(QString::fromStdString(entityName(scene, {info.refersTo, x})));
            else {
                constexpr int n = T::length();
                QJSValue array = engine->newArray(n);
                for (int i = 0; i < n; ++i) array.setProperty(quint32(i), double(x[i]));
                return array;
            }
        },
        value);
}

} // namespace

AppApi::AppApi(MainWindow* window, QJSEngine* engine)
    : QObject(engine), m_window(window), m_engine(engine) {
    setObjectName("app");
}

bool AppApi::fail(const QString& message) {
    m_engine->throwError(QJSValue::GenericError, message);
    return false;
}

bool AppApi::openScene(const QString& path) {
    SceneDocument* document = m_window->document();
    bool done = false;
    QString error;
    QMetaObject::Connection ok = connect(document, &SceneDocument::sceneOpened, this, [&] { done = true; });
    QMetaObject::Connection bad = connect(document, &SceneDocument::openFailed, this,
                                          [&](const QString& message) { done = true; error = message; });
    document->open(path);
    waitUntil([&] { return done; }, QDeadlineTimer::Forever);
    disconnect(ok);
    disconnect(bad);
    return error.isEmpty() ? true : fail(error);
}

int AppApi::waitForSamples(int spp, double timeoutSeconds) {
    RenderController* render = m_window->renderer();
    QString error;
    // Any error (a render failure, the scene failing to load) ends the wait.
    QMetaObject::Connection failed = connect(m_window->errors(), &ErrorReporter::reported, this,
                                             [&](const QString& message) { error = message; });
    const bool reached = waitUntil(
        [&] { return !error.isEmpty() || render->latestFrame().samplesPerPixel >= spp; },
        QDeadlineTimer(qint64(timeoutSeconds * 1000.0)));
    disconnect(failed);
    if (!error.isEmpty()) return fail(error), 0;
    if (!reached)
        return fail(QStringLiteral("waitForSamples(%1): only %2 spp after %3 s")
                        .arg(spp)
                        .arg(render->latestFrame().samplesPerPixel)
                        .arg(timeoutSeconds)),
               0;
    return render->latestFrame().samplesPerPixel;
}

bool AppApi::saveImage(const QString& path) {
    const RenderFrame& frame = m_window->renderer()->latestFrame();
    if (!frame.image) return fail("saveImage: no frame has been rendered yet");
    auto status = scene::writeImage(path.toStdString(), *frame.image, m_window->viewport()->exposure());
    return status ? true : fail(QString::fromStdString(status.error().message()));
}

bool AppApi::waitForSave(const std::function<void()>& start) {
    SceneDocument* document = m_window->document();
    bool done = false;
    QString error;
    QMetaObject::Connection ok = connect(document, &SceneDocument::saved, this, [&] { done = true; });
    QMetaObject::Connection bad = connect(document, &SceneDocument::saveFailed, this,
                                          [&](const QString& message) { done = true; error = message; });
    start();
    waitUntil([&] { return done; }, QDeadlineTimer::Forever);
    disconnect(ok);
    disconnect(bad);
    return error.isEmpty() ? true : fail(error);
}

bool AppApi::save() {
    if (!m_window->document()->scene()) return fail("save: no scene is open");
    return waitForSave([this] { m_window->document()->save(); });
}

bool AppApi::saveScene(const QString& path, const QString& lighting) {
    std::optional<LightingSave> choice;
    if (!lighting.isEmpty()) {
        choice = parseLightingSave(lighting.toStdString());
        if (!choice)
            return fail(QStringLiteral("saveScene: lighting must be \"copy\", \"inline\", \"setup\" or "
                                       "\"reference\", not \"%1\"").arg(lighting));
    }
    return waitForSave([this, path, choice] { m_window->document()->saveAs(path, choice); });
}

bool AppApi::answerPrompts(const QString& answer) {
    std::optional<PromptAnswer> parsed;
    if (answer == "save") parsed = PromptAnswer::Save;
    else if (answer == "discard") parsed = PromptAnswer::Discard;
    else if (answer == "cancel") parsed = PromptAnswer::Cancel;
    else if (!answer.isEmpty())
        return fail(QStringLiteral("answerPrompts: expected \"save\", \"discard\", \"cancel\" or \"\", not \"%1\"")
                        .arg(answer));
    m_window->actions()->prompt()->setScriptedAnswer(parsed);
    return true;
}

bool AppApi::isModified() const { return m_window->document()->isModified(); }

bool AppApi::autosave() {
    AutosaveController* autosave = m_window->autosave();
    waitUntil([&] { return !autosave->isWriting(); }, QDeadlineTimer::Forever); // one in flight
    if (!autosave->autosaveNow()) return false;
    waitUntil([&] { return !autosave->isWriting(); }, QDeadlineTimer::Forever);
    return !recoveryFile().isEmpty();
}

QString AppApi::recoveryFile() const {
    const auto recovery = m_window->autosave()->store().find(m_window->document()->path());
    return recovery ? recovery->recoveryFile : QString();
}

bool AppApi::answerRecovery(const QString& answer) {
    std::optional<RecoveryAnswer> parsed;
    if (answer == "recover") parsed = RecoveryAnswer::Recover;
    else if (answer == "discard") parsed = RecoveryAnswer::Discard;
    else if (answer == "keep") parsed = RecoveryAnswer::Keep;
    else if (!answer.isEmpty())
        return fail(QStringLiteral("answerRecovery: expected \"recover\", \"discard\", \"keep\" or \"\", not \"%1\"")
                        .arg(answer));
    m_window->autosave()->setScriptedAnswer(parsed);
    return true;
}

QString AppApi::windowTitle() const {
    QString title = m_window->windowTitle();
    return title.replace("[*]", m_window->isWindowModified() ? "*" : "");
}

bool AppApi::grabWindow(const QString& path) {
    if (!m_window->grab().save(path))
        return fail(QStringLiteral("grabWindow: could not write '%1'").arg(path));
    return true;
}

bool AppApi::setProperty(const QString& entity, const QString& name, const QJSValue& value) {
    auto scene = m_window->document()->scene();
    if (!scene) return fail("setProperty: no scene is open");
    auto ref = resolveEntity(*scene, entity.toStdString());
    if (!ref) return fail("setProperty: " + QString::fromStdString(ref.error().message()));
    const scene::PropertyInfo* info = scene::findProperty(ref->kind, name.toStdString());
    if (!info)
        return fail(QStringLiteral("setProperty: %1 has no property '%2'")
                        .arg(scene::entityKindName(ref->kind), name));
    auto converted = toPropertyValue(*scene, *info, value);
    if (!converted)
        return fail(QStringLiteral("setProperty: '%1' expects a %2 value, got %3")
                        .arg(name, scene::propertyTypeName(info->type), value.toString()));
    auto status = m_window->document()->apply({*ref, name.toStdString(), *converted});
    return status ? true : fail(QString::fromStdString(status.error().message()));
}

QJSValue AppApi::getProperty(const QString& entity, const QString& name) {
    auto scene = m_window->document()->scene();
    if (!scene) return fail("getProperty: no scene is open"), QJSValue();
    auto ref = resolveEntity(*scene, entity.toStdString());
    if (!ref) return fail("getProperty: " + QString::fromStdString(ref.error().message())), QJSValue();
    const scene::PropertyInfo* info = scene::findProperty(ref->kind, name.toStdString());
    auto value = scene::getProperty(*scene, *ref, name.toStdString());
    if (!info || !value)
        return fail(QStringLiteral("getProperty: %1 has no property '%2'")
                        .arg(scene::entityKindName(ref->kind), name)),
               QJSValue();
    return toJsValue(m_engine, *scene, *info, *value);
}

bool AppApi::triggerAction(const QString& objectName) {
    auto* action = m_window->findChild<QAction*>(objectName);
    if (!action) return fail(QStringLiteral("triggerAction: no action named '%1'").arg(objectName));
    action->trigger();
    return true;
}

bool AppApi::select(const QString& entity) {
    auto scene = m_window->document()->scene();
    if (!scene) return fail("select: no scene is open");
    auto ref = resolveEntity(*scene, entity.toStdString());
    if (!ref) return fail("select: " + QString::fromStdString(ref.error().message()));
    if (!m_window->outline()->select(*ref))
        return fail(QStringLiteral("select: '%1' is not in the outline").arg(entity));
    return true;
}

int AppApi::samples() const { return m_window->renderer()->latestFrame().samplesPerPixel; }

QString AppApi::scenePath() const { return m_window->document()->path(); }

QStringList AppApi::entities() const {
    QStringList names;
    QTreeWidget* tree = m_window->outline()->tree();
    for (QTreeWidgetItemIterator it(tree); *it; ++it)
        if ((*it)->flags() & Qt::ItemIsSelectable) names << (*it)->text(0);
    return names;
}

QString AppApi::environment(const QString& name) const {
    return qEnvironmentVariable(name.toLocal8Bit().constData());
}

void AppApi::quit(int exitCode) {
    m_quit = true;
    m_exitCode = exitCode;
}

} // namespace wavelit::editor
