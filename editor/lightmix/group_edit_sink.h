// GroupEditSink: applies the LightMix panel's group edits (panels/lightmix_panel.h) — several
// properties as one change set, e.g. every light of a group scaled by one factor — to the
// document as ONE undo step each (SceneDocument::applyChanges), so the render thread receives
// the group's members changed together and remixes instead of restarting. The steps of one
// slider drag (one gesture) are collected into one undo macro that the drag's end closes, so a
// drag undoes as one step, as a single light's slider drag does.
#pragma once

#include "commands/property_edit.h"

#include "scene/change_set.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>

namespace wavelit::editor {

class SceneDocument;

class GroupEditSink : public QObject {
    Q_OBJECT
public:
    GroupEditSink(SceneDocument* document, std::function<void(const QString&)> report, QObject* parent = nullptr);
    ~GroupEditSink() override; // closes a macro a drag left open

    void apply(const scene::ChangeSet& changes, const QString& text, GestureId gesture);
    void endGesture();

private:
    QPointer<SceneDocument> m_document; // may go first when the window closes
    std::function<void(const QString&)> m_report;
    GestureId m_macroGesture = kNoGesture; // the gesture whose macro is open
};

} // namespace wavelit::editor
