// The start-up's second thread (editor/app/startupwarmup.h): the main thread
// waits for fontconfig only, and finishing never waits for a step that will
// not come (a start that exits after reading its command line).

#include "editor/app/startupwarmup.h"

#include <QDBusConnection>
#include <QFontDatabase>
#include <QTest>

#include <chrono>
#include <future>

using namespace editor;

namespace {

// Runs `step` on another thread and tells whether it returned within a
// generous time (a deadlock never does).
template <typename Step>
bool returnsPromptly(Step step)
{
    auto done = std::async(std::launch::async, step);
    return done.wait_for(std::chrono::seconds(20)) == std::future_status::ready;
}

} // namespace

class TestStartupWarmUp : public QObject {
    Q_OBJECT

private slots:
    void fontconfigIsReadyBeforeTheApplication();
    void finishesWithoutTheApplicationStep();
    void finishesAfterTheApplicationStep();
    void finishingTwiceIsHarmless();
};

void TestStartupWarmUp::fontconfigIsReadyBeforeTheApplication()
{
    // The main thread waits for fontconfig while the warm-up still waits
    // for applicationReady(): the two must not wait for each other.
    auto warmUp = std::make_shared<StartupWarmUp>();
    QVERIFY(returnsPromptly([warmUp] { warmUp->waitForFontconfig(); }));
    QVERIFY(returnsPromptly([warmUp] { warmUp->finish(); }));
}

void TestStartupWarmUp::finishesWithoutTheApplicationStep()
{
    QVERIFY(returnsPromptly([] {
        StartupWarmUp warmUp;
        warmUp.finish();
    }));
    // Destroyed without a word: the destructor finishes.
    QVERIFY(returnsPromptly([] { StartupWarmUp warmUp; }));
}

void TestStartupWarmUp::finishesAfterTheApplicationStep()
{
    auto warmUp = std::make_shared<StartupWarmUp>();
    warmUp->applicationReady();
    warmUp->waitForFontconfig();
    QVERIFY(returnsPromptly([warmUp] { warmUp->finish(); }));
    // What it prepared is the process's: the main thread finds it at once.
    QVERIFY(!QFontDatabase::families().isEmpty());
    QVERIFY(returnsPromptly([] { QDBusConnection::sessionBus(); }));
}

void TestStartupWarmUp::finishingTwiceIsHarmless()
{
    StartupWarmUp warmUp;
    warmUp.applicationReady();
    warmUp.finish();
    warmUp.finish();
    warmUp.waitForFontconfig();
}

QTEST_MAIN(TestStartupWarmUp)
#include "test_startupwarmup.moc"
