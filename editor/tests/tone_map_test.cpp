// Display tone mapping: the sRGB table against the exact curve, exposure as a power of two, and
// that pixels keep their place (row 0 on top).
#include "viewport/tone_map.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace wavelit;

namespace {
int exactSrgb8(double linear) {
    double c = std::clamp(linear, 0.0, 1.0);
    double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return int(std::lround(s * 255.0));
}
} // namespace

class ToneMapTest : public QObject {
    Q_OBJECT
private slots:
    void anchors() {
        QCOMPARE(editor::linearToSrgb8(0.0f), 0);
        QCOMPARE(editor::linearToSrgb8(1.0f), 255);
        QCOMPARE(editor::linearToSrgb8(0.5f), 188); // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
        QCOMPARE(editor::linearToSrgb8(0.18f), 118); // mid grey: 0.4614
        QCOMPARE(editor::linearToSrgb8(0.002f), 7);  // linear segment: 12.92 * 0.002 * 255 = 6.6
    }
    void nonFiniteAndOutOfRange() {
        QCOMPARE(editor::linearToSrgb8(-1.0f), 0);
        QCOMPARE(editor::linearToSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
        QCOMPARE(editor::linearToSrgb8(std::numeric_limits<float>::infinity()), 255);
        QCOMPARE(editor::linearToSrgb8(7.5f), 255);
    }
    void tableMatchesExactCurve() {
        // The table quantises its input; its output may differ from the exact curve by at most
        // one 8-bit step (see the table size comment in tone_map.cpp).
        int worst = 0;
        for (int i = 0; i <= 100000; ++i) {
            const double x = double(i) / 100000.0;
            worst = std::max(worst, std::abs(editor::linearToSrgb8(float(x)) - exactSrgb8(x)));
        }
        QVERIFY2(worst <= 1, qPrintable(QString("worst difference %1 steps").arg(worst)));
    }
    void exposureIsPowerOfTwoAndLayoutKept() {
        util::ImageRGB image(3, 2);
        image.at(0, 0) = {0.25f, 0.0f, 0.0f}; // top-left: red
        image.at(2, 1) = {0.0f, 0.0f, 0.125f}; // bottom-right: blue
        const QImage base = editor::toneMap(image, 0.0f);
        const QImage brighter = editor::toneMap(image, 1.0f);
        QCOMPARE(base.size(), QSize(3, 2));
        QCOMPARE(qRed(base.pixel(0, 0)), editor::linearToSrgb8(0.25f));
        QCOMPARE(qRed(brighter.pixel(0, 0)), editor::linearToSrgb8(0.5f));
        QCOMPARE(qBlue(brighter.pixel(2, 1)), editor::linearToSrgb8(0.25f));
        QCOMPARE(qBlue(editor::toneMap(image, 3.0f).pixel(2, 1)), 255);
        QCOMPARE(base.pixel(1, 0), qRgb(0, 0, 0));
        QVERIFY(editor::toneMap(util::ImageRGB(), 0.0f).isNull());
    }
};

QTEST_APPLESS_MAIN(ToneMapTest)
#include "tone_map_test.moc"
