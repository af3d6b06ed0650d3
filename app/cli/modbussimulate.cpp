#include "modbussimulate.h"

#include "terminal.h"

#include "core/formats/fileio.h"
#include "core/link/modbusmap.h"
#include "core/model/model.h"
#include "core/simulation/simulator.h"
#include "editor/modbus/modbuslink.h"

#include <QCoreApplication>
#include <QTimer>

#include <csignal>
#include <memory>
#include <optional>
#include <ostream>

namespace cli {

namespace modbussimulate {

volatile std::sig_atomic_t stopRequested = 0;

extern "C" void onStopSignal(int)
{
    stopRequested = 1;
}

// The mapping as a table: "  coil 0   EmergencyOk  BOOL input".
void printMap(const core::modbusio::ModbusMap& map, std::ostream& out)
{
    for (const core::modbusio::ModbusEntry& entry : map.entries) {
        std::string where = std::string(core::modbusio::modbusTableName(entry.table)) + " " + std::to_string(entry.address);
        if (entry.width > 1)
            where += ".." + std::to_string(entry.address + entry.width - 1);
        where.resize(std::max<std::size_t>(where.size(), 24), ' ');
        out << "  " << where << entry.variable << " (" << core::iecTypeName(entry.type) << " "
            << core::variableKindName(entry.kind) << ")" << lineEnd;
    }
    if (map.entries.empty())
        out << "  (no variable linked)" << lineEnd;
}

} // namespace modbussimulate

int simulateModbus(const Arguments& args, const std::string& path, const core::Model& model, std::int64_t scans,
                   Streams streams)
{
    using namespace modbussimulate;
    const bool server = args.has("--modbus-server");
    const bool client = args.has("--modbus-client");
    if (server && client) {
        streams.err << "ggstudio-cli: --modbus-server and --modbus-client exclude each other" << lineEnd;
        return UsageError;
    }
    if (!server && !client && !args.has("--print-modbus-map")) {
        streams.err << "ggstudio-cli: --modbus-map and --unit-id need --modbus-server or --modbus-client" << lineEnd;
        return UsageError;
    }
    const core::modbusio::ModbusRole role = client ? core::modbusio::ModbusRole::Client : core::modbusio::ModbusRole::Server;
    core::modbusio::ModbusMap map = core::modbusio::defaultModbusMap(model.variables(), role);
    if (auto mapPath = args.value("--modbus-map")) {
        std::string text;
        if (core::Status status = core::readFileLimited(*mapPath, 4u * 1024u * 1024u, text); !status) {
            streams.err << *mapPath << ": " << status.message << lineEnd;
            return UnreadableInput;
        }
        const core::modbusio::ModbusMapParse parsed = core::modbusio::parseModbusMap(text, model.variables(), role);
        for (const core::modbusio::ModbusMapError& error : parsed.errors)
            streams.err << error.toString(*mapPath) << lineEnd;
        if (!parsed.ok())
            return UnreadableInput;
        map = parsed.map;
    }
    if (args.has("--print-modbus-map")) {
        writeVerbatim(streams.out, core::modbusio::writeModbusMap(map));
        return Success;
    }
    int unitId = 1;
    if (auto given = args.value("--unit-id")) {
        bool ok = false;
        unitId = QString::fromStdString(*given).toInt(&ok);
        if (!ok || unitId < 0 || unitId > 255) {
            streams.err << "ggstudio-cli: --unit-id takes a number in 0..255, not '" << *given << "'" << lineEnd;
            return UsageError;
        }
    }
    const std::string option = server ? "--modbus-server" : "--modbus-client";
    modbus::ModbusLinkOptions options;
    options.map = map;
    options.unitId = unitId;
    options.cycleTimeMs = model.settings().cycleTimeMs;
    QString error;
    if (!modbus::parseHostPort(QString::fromStdString(*args.value(option)), options.host, options.port, error)) {
        streams.err << "ggstudio-cli: " << option << ": " << error.toStdString() << lineEnd;
        return UnreadableInput;
    }

    int argc = 1;
    char name[] = "ggstudio-cli";
    char* argv[] = {name, nullptr};
    std::optional<QCoreApplication> application;
    if (!QCoreApplication::instance())
        application.emplace(argc, argv);

    core::Simulator simulator(model);
    modbus::ModbusScanHooks hooks = modbus::simulatorHooks(simulator);
    bool faulted = false;
    hooks.scan = [&] {
        if (faulted)
            return;
        const core::ScanRecord record = simulator.step();
        if (const auto& fault = simulator.fault()) {
            streams.err << path << ": " << core::toText(*fault) << lineEnd;
            faulted = true;
            QCoreApplication::quit();
            return;
        }
        if (!record.fired.empty())
            streams.out << "scan " << record.scan << ": " << record.stepAfter << " fired " << record.fired << lineEnd;
    };
    modbus::ModbusLink link(options, hooks);
    QObject::connect(&link, &modbus::ModbusLink::linkError, [&](const QString& message) {
        streams.err << "modbus: " << message.toStdString() << lineEnd;
    });
    QObject::connect(&link, &modbus::ModbusLink::inputApplied, [&](const QString& variable, const QString& value) {
        streams.out << "scan " << simulator.scanCount() + 1 << ": modbus set " << variable.toStdString() << " = "
                    << value.toStdString() << lineEnd;
    });
    QObject::connect(&link, &modbus::ModbusLink::clientsChanged, [&](int count) {
        streams.out << "modbus: " << count << " client(s) connected" << lineEnd;
    });
    QObject::connect(&link, &modbus::ModbusLink::stateChanged, [&] {
        if (link.state() == modbus::ModbusLink::State::Connected)
            streams.out << "modbus: connected to " << options.host.toStdString() << ":" << options.port << lineEnd;
    });
    QObject::connect(&link, &modbus::ModbusLink::scanned, [&](std::int64_t done) {
        if (scans > 0 && done >= scans)
            QCoreApplication::quit();
    });

    streams.out << "Modbus map (" << (server ? "server" : "client") << " mode, unit " << unitId << "):" << lineEnd;
    printMap(map, streams.out);
    if (!link.start(&error)) {
        streams.err << "ggstudio-cli: " << error.toStdString() << lineEnd;
        return UnreadableInput;
    }
    // The handlers before the line that says how to stop.
    stopRequested = 0;
    auto previousInt = std::signal(SIGINT, onStopSignal);
    auto previousTerm = std::signal(SIGTERM, onStopSignal);
    streams.out << (server ? "listening on " : "connecting to ") << options.host.toStdString() << ":" << options.port
                << ", cycle time " << options.cycleTimeMs << " ms"
                << (scans > 0 ? ", " + std::to_string(scans) + " scans" : std::string(", until SIGINT or SIGTERM"))
                << lineEnd;
    streams.out.flush();

    QTimer watch;
    QObject::connect(&watch, &QTimer::timeout, [] {
        if (stopRequested)
            QCoreApplication::quit();
    });
    watch.start(50);
    QCoreApplication::exec();
    watch.stop();
    link.stop();
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
    streams.out << "stopped after " << link.scansRun() << " scans, " << simulator.activeStepId() << lineEnd;
    return faulted ? RunTimeFault : Success;
}

} // namespace cli
