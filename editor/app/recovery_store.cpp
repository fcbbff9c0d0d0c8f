#include "app/recovery_store.h"

#include "app/save_plan.h"

#include "scene/atomic_file.h"
#include "scene/scene_io.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

#include <filesystem>

namespace wavelit::editor {
namespace {

QString keyFor(const QString& scenePath) {
    if (scenePath.isEmpty()) return "untitled";
    const QByteArray absolute = QFileInfo(scenePath).absoluteFilePath().toUtf8();
    return QString::fromLatin1(QCryptographicHash::hash(absolute, QCryptographicHash::Sha1).toHex().left(16));
}

QString sidecarOf(const QString& recoveryFile) {
    return recoveryFile.left(recoveryFile.size() - int(QStringLiteral(".wlscene").size())) + ".json";
}

util::Error recoveryError(const QString& file, const std::string& reason) {
    return util::makeError(util::ErrorKind::Invalid, file.toStdString(), reason);
}

} // namespace

RecoveryStore::RecoveryStore(QString folder) : m_folder(std::move(folder)) {}

QString RecoveryStore::defaultFolder() {
    const QString configured = qEnvironmentVariable("WAVELIT_RECOVERY_DIR");
    if (!configured.isEmpty()) return configured;
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + "/recovery";
}

QString RecoveryStore::recoveryFileFor(const QString& scenePath) const {
    return QDir(m_folder).filePath(keyFor(scenePath) + ".wlscene");
}

util::Status RecoveryStore::write(const scene::Scene& scene, const QString& scenePath) const {
    if (!QDir().mkpath(m_folder))
        return recoveryError(m_folder, "cannot create the recovery folder");
    const QString file = recoveryFileFor(scenePath);
    auto plan = planSave(scene, scenePath.toStdString(), file.toStdString(), LightingSave::Inline, true);
    if (!plan) return plan.error();
    if (auto status = scene::saveScene(*plan->scene, file.toStdString()); !status) return status;
    QJsonObject meta;
    meta["scene"] = scenePath.isEmpty() ? QString() : QFileInfo(scenePath).absoluteFilePath();
    meta["lighting"] = QString::fromStdString(lightingFileOf(scene, scenePath.toStdString()));
    meta["saved"] = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    return scene::writeFileAtomic(sidecarOf(file).toStdString(),
                                  QJsonDocument(meta).toJson().toStdString());
}

std::optional<Recovery> RecoveryStore::find(const QString& scenePath) const {
    const QString file = recoveryFileFor(scenePath);
    QFile sidecar(sidecarOf(file));
    if (!QFileInfo::exists(file) || !sidecar.open(QIODevice::ReadOnly)) return std::nullopt;
    const QJsonObject meta = QJsonDocument::fromJson(sidecar.readAll()).object();
    Recovery recovery{file, meta["scene"].toString(),
                      QDateTime::fromString(meta["saved"].toString(), Qt::ISODateWithMs)};
    // A scene saved after the recovery was written supersedes it.
    const QFileInfo original(scenePath);
    if (!recovery.saved.isValid() ||
        (original.exists() && original.lastModified().toUTC() > recovery.saved))
        return std::nullopt;
    return recovery;
}

util::Result<RecoveredDocument> RecoveryStore::read(const Recovery& recovery) const {
    QFile sidecar(sidecarOf(recovery.recoveryFile));
    if (!sidecar.open(QIODevice::ReadOnly)) return recoveryError(sidecarOf(recovery.recoveryFile), "cannot be read");
    const QString lightingFile = QJsonDocument::fromJson(sidecar.readAll()).object()["lighting"].toString();
    auto loaded = scene::loadScene(recovery.recoveryFile.toStdString());
    if (!loaded) return loaded.error();
    scene::Scene scene = std::move(loaded.value());
    const QString target = recovery.scenePath.isEmpty() ? recovery.recoveryFile : recovery.scenePath;
    scene::rebaseScenePaths(scene, recovery.recoveryFile.toStdString(), target.toStdString());
    RecoveredDocument out;
    if (!lightingFile.isEmpty()) {
        // Back to a reference: the edited lighting stays in the document, the file stays as it is.
        const QString sceneFolder = QFileInfo(target).absolutePath();
        const QString setupFolder = QFileInfo(lightingFile).absolutePath();
        scene.lighting.environment.path = rebaseRelativePath(scene.lighting.environment.path,
                                                              sceneFolder.toStdString(), setupFolder.toStdString());
        scene.lightingPath = QDir(sceneFolder).relativeFilePath(lightingFile).toStdString();
        auto setup = scene::loadLightingSetup(lightingFile.toStdString());
        out.savedLighting = setup ? std::move(setup.value()) : scene::LightingSetup{};
    }
    out.scene = std::make_shared<const scene::Scene>(std::move(scene));
    return out;
}

void RecoveryStore::remove(const QString& scenePath) const {
    const QString file = recoveryFileFor(scenePath);
    QFile::remove(file);
    QFile::remove(sidecarOf(file));
}

} // namespace wavelit::editor
