#include "panels/gesture_tracker.h"

#include <QEvent>
#include <QKeyEvent>

namespace wavelit::editor {

GestureTracker::GestureTracker(QObject* parent) : QObject(parent) {}

void GestureTracker::watch(QObject* widget) { widget->installEventFilter(this); }

void GestureTracker::begin() {
    m_gesture = newGestureId();
    m_pressed = true;
    m_scrubbing = false;
}

void GestureTracker::end() {
    m_pressed = false;
    m_gesture = kNoGesture;
}

GestureId GestureTracker::current() {
    if (m_scrubbing && m_lastScrub.elapsed() > kScrubPauseMs) {
        m_scrubbing = false;
        m_gesture = kNoGesture;
    }
    return m_gesture;
}

void GestureTracker::scrub() {
    if (m_pressed) return; // a wheel turn during a drag belongs to the drag
    if (!m_scrubbing || m_lastScrub.elapsed() > kScrubPauseMs) m_gesture = newGestureId();
    m_scrubbing = true;
    m_lastScrub.start();
}

bool GestureTracker::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick: begin(); break;
    case QEvent::MouseButtonRelease: end(); break;
    case QEvent::Wheel: scrub(); break;
    case QEvent::KeyPress:
        // Each key press is an edit of its own; its auto-repeats (an arrow key held) join it.
        if (m_pressed) break;
        if (!static_cast<QKeyEvent*>(event)->isAutoRepeat()) m_scrubbing = false;
        scrub();
        break;
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace wavelit::editor
