// Catch2 BENCHMARK behind the README's Modbus figure: the round trip of the
// simulator as a Modbus TCP server on loopback. A QModbusTcpClient (the twin)
// writes an input (the drilling cell's StartButton coil) and reads until the
// output it drives (Spindle's discrete input) changes; the time is reported in
// the model's cycle times (issue 35's budget: at most 2). The model's own path
// takes two scans (scan k fires A1->F2, scan k+1 runs F2's GRAFCET, which sets
// Spindle), so the figure is the wait for those scans, which depends on when
// in the cycle the write lands (spread evenly over the cycle here, as a
// twin's writes are), plus the transport: from the scan that set Spindle
// to the twin reading it, printed apart. Each round trip has a fresh
// simulator and link (the set-up is not timed). 127.0.0.1 only, every wait
// bounded. Nothing here asserts a time.

#include <catch2/catch.hpp>

#include "benchrepeats.h"
#include "catchsession.h"

#include "core/formats/modelfiles.h"
#include "core/link/modbusmap.h"
#include "core/simulation/simulator.h"
#include "editor/modbus/modbuslink.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QModbusReply>
#include <QModbusTcpClient>
#include <QTcpServer>
#include <QVariant>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

namespace bench_modbus {

// Runs the event loop until `done` or the deadline; false on the deadline.
template <typename Predicate>
bool spinUntil(Predicate done, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    while (!done()) {
        if (deadline.hasExpired())
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
    }
    return true;
}

// The reply's value, or -1 when it failed or did not come in time.
int await(QModbusReply* reply)
{
    if (!reply)
        return -1;
    std::unique_ptr<QModbusReply> owned(reply);
    if (!spinUntil([&] { return reply->isFinished(); }, 2000) || reply->error() != QModbusDevice::NoError)
        return -1;
    return reply->result().valueCount() > 0 ? reply->result().value(0) : 0;
}

// A fresh drilling cell behind a server link, and its twin connected.
struct Rig {
    std::unique_ptr<core::Model> model;
    std::unique_ptr<core::Simulator> simulator;
    std::unique_ptr<modbus::ModbusLink> link;
    QModbusTcpClient twin;
    core::modbusio::ModbusMap map;
    bool ready = false;

    Rig()
    {
        model = core::loadModelFile(GGSTUDIO_EXAMPLES_DIR "/drilling-cell.ggstudio.json").model;
        if (!model)
            return;
        simulator = std::make_unique<core::Simulator>(*model);
        QTcpServer probe;
        if (!probe.listen(QHostAddress::LocalHost, 0))
            return;
        const int port = probe.serverPort();
        probe.close();
        modbus::ModbusLinkOptions options;
        map = core::modbusio::defaultModbusMap(model->variables(), core::modbusio::ModbusRole::Server);
        options.map = map;
        options.port = port;
        options.cycleTimeMs = simulator->cycleTimeMs();
        link = std::make_unique<modbus::ModbusLink>(options, modbus::simulatorHooks(*simulator));
        if (!link->start(nullptr))
            return;
        twin.setConnectionParameter(QModbusDevice::NetworkAddressParameter, QStringLiteral("127.0.0.1"));
        twin.setConnectionParameter(QModbusDevice::NetworkPortParameter, port);
        twin.setTimeout(2000);
        twin.setNumberOfRetries(0);
        if (!twin.connectDevice()
            || !spinUntil([&] { return twin.state() == QModbusDevice::ConnectedState; }, 3000))
            return;
        // The machine at rest, as its sensors say; then let a few scans read it.
        QModbusDataUnit rest(QModbusDataUnit::Coils, map.find("Unclamped")->address, 2); // Unclamped, DrillHigh
        rest.setValue(0, 1);
        rest.setValue(1, 1);
        if (await(twin.sendWriteRequest(rest, 1)) < 0)
            return;
        const std::int64_t scans = link->scansRun();
        ready = spinUntil([&] { return link->scansRun() >= scans + 3; }, 2000);
    }

    ~Rig()
    {
        twin.disconnectDevice();
        if (link)
            link->stop();
    }

    // Writes StartButton, reads Spindle until it is on: milliseconds, or -1.
    // Milliseconds from the write to the end of the scan that set Spindle.
    double published = -1.0;

    double roundTrip()
    {
        QElapsedTimer clock;
        clock.start();
        published = -1.0;
        QObject::connect(link.get(), &modbus::ModbusLink::scanned, link.get(), [this, &clock] {
            if (published < 0.0 && simulator->variable("Spindle") == core::cond::Value(true))
                published = static_cast<double>(clock.nsecsElapsed()) / 1e6;
        });
        QModbusDataUnit press(QModbusDataUnit::Coils, map.find("StartButton")->address, 1);
        press.setValue(0, 1);
        if (await(twin.sendWriteRequest(press, 1)) < 0)
            return -1.0;
        const int spindle = map.find("Spindle")->address;
        for (int i = 0; i < 1000 && clock.elapsed() < 3000; ++i) {
            if (await(twin.sendReadRequest(QModbusDataUnit(QModbusDataUnit::DiscreteInputs, spindle, 1), 1)) == 1)
                return static_cast<double>(clock.nsecsElapsed()) / 1e6;
        }
        return -1.0;
    }
};

TEST_CASE("Modbus round trip", "[modbus]")
{
    const int rounds = benchRepeats(20);
    std::vector<double> cycles;
    std::vector<double> transport;
    int cycleMs = 0;
    for (int i = 0; i < rounds; ++i) {
        Rig rig;
        REQUIRE(rig.ready);
        cycleMs = rig.simulator->cycleTimeMs();
        // The write lands at i/rounds of the cycle after a scan.
        const int scans = static_cast<int>(rig.link->scansRun());
        REQUIRE(spinUntil([&] { return rig.link->scansRun() > scans; }, 2000));
        QElapsedTimer phase;
        phase.start();
        const double delayMs = static_cast<double>(cycleMs) * i / rounds;
        spinUntil([&] { return static_cast<double>(phase.nsecsElapsed()) / 1e6 >= delayMs; }, cycleMs);
        const double ms = rig.roundTrip();
        REQUIRE(ms >= 0.0);
        REQUIRE(rig.published >= 0.0);
        cycles.push_back(ms / cycleMs);
        transport.push_back(ms - rig.published);
    }
    std::sort(cycles.begin(), cycles.end());
    std::sort(transport.begin(), transport.end());
    std::printf("\nModbus round trip on loopback (client writes StartButton, reads until Spindle is on: two scans\n"
                "of the model), drilling cell, cycle time %d ms, %d rounds, writes spread over the cycle:\n"
                "  median %.2f cycle times (%.1f ms), worst %.2f; from the scan to the twin's read: median %.2f ms\n\n",
                cycleMs, rounds, cycles[cycles.size() / 2], cycles[cycles.size() / 2] * cycleMs, cycles.back(),
                transport[transport.size() / 2]);
    std::fflush(stdout);

    BENCHMARK_ADVANCED("Modbus round trip, one write and the reads until the output changes")
    (Catch::Benchmark::Chronometer meter)
    {
        std::vector<std::unique_ptr<Rig>> rigs;
        for (int r = 0; r < meter.runs(); ++r)
            rigs.push_back(std::make_unique<Rig>());
        meter.measure([&](int r) { return rigs[static_cast<std::size_t>(r)]->roundTrip(); });
    };
}

} // namespace bench_modbus

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    return runCatchSession(argc, argv);
}
