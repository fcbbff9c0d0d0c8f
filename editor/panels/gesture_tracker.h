// GestureTracker: tells which user gesture a widget's value change belongs to, so the edits of one
// slider drag or spin-box scrub undo as one step (commands/property_command.h) while separate
// edits stay separate. Installed as an event filter on the editing widget(s):
//   - mouse press .. release (a slider drag, an arrow button held down) is one gesture;
//   - wheel notches closer than kScrubPauseMs to the previous one continue the gesture they
//     started; a key press starts a gesture of its own that only its auto-repeats join;
//   - a change that arrives some other way (a programmatic setValue, focus loss after typing) is
//     no gesture: current() is kNoGesture and the edit stands alone.
// A QSlider's sliderPressed/sliderReleased can drive begin()/end() directly (keyboard-free drags
// from tests or accessibility tools arrive that way).
#pragma once

#include "commands/property_edit.h"

#include <QElapsedTimer>
#include <QObject>

namespace wavelit::editor {

class GestureTracker : public QObject {
    Q_OBJECT
public:
    static constexpr int kScrubPauseMs = 500;

    explicit GestureTracker(QObject* parent = nullptr);

    void watch(QObject* widget); // installs the event filter
    void begin();                // a new gesture (ends any running one)
    void end();
    void scrub();                // a wheel notch: continues a recent scrub or starts one
    GestureId current();         // the running gesture, or kNoGesture

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    GestureId m_gesture = kNoGesture;
    bool m_pressed = false;
    bool m_scrubbing = false;
    QElapsedTimer m_lastScrub;
};

} // namespace wavelit::editor
