#include "app/editor_options.h"

#include <QRegularExpression>

#include <optional>

namespace wavelit::editor {
namespace {

util::Error usage(const QString& reason) {
    return util::makeError(util::ErrorKind::Usage, "", reason.toStdString());
}

} // namespace

QString defaultScenePath() {
    const QByteArray overridePath = qgetenv("WAVELIT_DEFAULT_SCENE");
    return overridePath.isEmpty() ? QStringLiteral(WAVELIT_DEFAULT_SCENE)
                                  : QString::fromLocal8Bit(overridePath);
}

QString editorUsage() {
    return QStringLiteral(
        "usage: wavelit [SCENE.wlscene] [--script FILE.js] [--device auto|vulkan|cpu]\n"
        "               [--sampler NAME] [--size WxH] [--max-spp N] [--validation] [--light-mix]\n"
        "With no scene, opens the bundled default scene (%1).\n")
        .arg(defaultScenePath());
}

util::Result<EditorOptions> parseEditorOptions(const QStringList& arguments) {
    EditorOptions options;
    bool sceneGiven = false;
    for (int i = 1; i < arguments.size(); ++i) {
        const QString& arg = arguments[i];
        auto next = [&]() -> std::optional<QString> {
            if (i + 1 >= arguments.size()) return std::nullopt;
            return arguments[++i];
        };
        if (arg == "--script" || arg == "--device" || arg == "--sampler" || arg == "--size" ||
            arg == "--max-spp") {
            auto value = next();
            if (!value) return usage(arg + " needs a value");
            if (arg == "--script") {
                options.scriptPath = *value;
            } else if (arg == "--device") {
                auto device = render::parseDeviceChoice(value->toStdString());
                if (!device) return device.error();
                options.render.device = *device;
            } else if (arg == "--sampler") {
                auto sampler = render::parseSamplerKind(value->toStdString());
                if (!sampler) return sampler.error();
                options.render.sampler = *sampler;
            } else if (arg == "--size") {
                static const QRegularExpression pattern("^(\\d{1,5})x(\\d{1,5})$");
                auto match = pattern.match(*value);
                const int w = match.hasMatch() ? match.captured(1).toInt() : 0;
                const int h = match.hasMatch() ? match.captured(2).toInt() : 0;
                if (w <= 0 || h <= 0) return usage("--size must be WxH with W, H > 0, got '" + *value + "'");
                options.render.width = w;
                options.render.height = h;
            } else {
                bool ok = false;
                const int spp = value->toInt(&ok);
                if (!ok || spp < 0) return usage("--max-spp must be a non-negative integer, got '" + *value + "'");
                options.render.maxSamplesPerPixel = spp;
            }
        } else if (arg == "--validation") {
            options.render.validation = true;
        } else if (arg == "--light-mix") {
            options.render.lightMix = true;
        } else if (arg.startsWith('-')) {
            return usage("unknown option '" + arg + "'");
        } else if (sceneGiven) {
            return usage("more than one scene given ('" + options.scenePath + "', '" + arg + "')");
        } else {
            options.scenePath = arg;
            sceneGiven = true;
        }
    }
    if (!sceneGiven) options.scenePath = defaultScenePath();
    return options;
}

} // namespace wavelit::editor
