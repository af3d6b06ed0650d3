<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>PasteVariablesCommand</name>
    <message numerus="yes">
        <source>Paste %n variables</source>
        <translation>
            <numerusform>Paste %n variable</numerusform>
            <numerusform>Paste %n variables</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SetElementsHiddenCommand</name>
    <message numerus="yes">
        <source>Hide %n element(s)</source>
        <translation>
            <numerusform>Hide %n element</numerusform>
            <numerusform>Hide %n elements</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show %n element(s)</source>
        <translation>
            <numerusform>Show %n element</numerusform>
            <numerusform>Show %n elements</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SpecificationExport</name>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n step</numerusform>
            <numerusform>%n steps</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n transition(s)</source>
        <translation>
            <numerusform>%n transition</numerusform>
            <numerusform>%n transitions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s): the generated code marks each one with a comment.</source>
        <translation>
            <numerusform>The model has %n error: the generated code marks it with a comment.</numerusform>
            <numerusform>The model has %n errors: the generated code marks each one with a comment.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::ChartContextMenu</name>
    <message numerus="yes">
        <source>Hide the %n Selected Elements</source>
        <translation>
            <numerusform>Hide the Selected Element</numerusform>
            <numerusform>Hide the %n Selected Elements</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show the %n Selected Elements</source>
        <translation>
            <numerusform>Show the Selected Element</numerusform>
            <numerusform>Show the %n Selected Elements</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::ExportActions</name>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… and %n more</numerusform>
            <numerusform>… and %n more</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s). The generated code marks each one with a comment, but it may not compile or may not behave as intended.</source>
        <translation>
            <numerusform>The model has %n error. The generated code marks each one with a comment, but it may not compile or may not behave as intended.</numerusform>
            <numerusform>The model has %n errors. The generated code marks each one with a comment, but it may not compile or may not behave as intended.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::GrafcetActions</name>
    <message numerus="yes">
        <source>Remove %n steps from %1</source>
        <translation>
            <numerusform>Remove %n step from %1</numerusform>
            <numerusform>Remove %n steps from %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Paste %n steps into %1</source>
        <translation>
            <numerusform>Paste %n step into %1</numerusform>
            <numerusform>Paste %n steps into %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remove %n transitions from %1</source>
        <translation>
            <numerusform>Remove %n transition from %1</numerusform>
            <numerusform>Remove %n transitions from %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remove %n elements from %1</source>
        <translation>
            <numerusform>Remove %n element from %1</numerusform>
            <numerusform>Remove %n elements from %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Cut %n steps from %1</source>
        <translation>
            <numerusform>Cut %n step from %1</numerusform>
            <numerusform>Cut %n steps from %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::GrafcetSimulationMarks</name>
    <message numerus="yes">
        <source>%1 is active: its GRAFCET runs (step(s) %2)</source>
        <translation>
            <numerusform>%1 is active: its GRAFCET runs (step %2)</numerusform>
            <numerusform>%1 is active: its GRAFCET runs (steps %2)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::ProblemCounter</name>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Verification (outdated): %n finding(s)</source>
        <extracomment>the verification&apos;s findings after the checks&apos; problems in the status bar</extracomment>
        <translation>
            <numerusform>Verification (outdated): %n finding</numerusform>
            <numerusform>Verification (outdated): %n findings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Verification: %n finding(s)</source>
        <translation>
            <numerusform>Verification: %n finding</numerusform>
            <numerusform>Verification: %n findings</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::ProblemsDock</name>
    <message numerus="yes">
        <source>%n errors</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warnings</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n infos</source>
        <translation>
            <numerusform>%n info</numerusform>
            <numerusform>%n infos</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Nested GRAFCET of %1: %n problems</source>
        <translation>
            <numerusform>Nested GRAFCET of %1: %n problem</numerusform>
            <numerusform>Nested GRAFCET of %1: %n problems</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::SimulationDock</name>
    <message numerus="yes">
        <source>%n other transition(s): an upstream step is not active</source>
        <extracomment>the transitions of a large nested GRAFCET left out of the explanation</extracomment>
        <translation>
            <numerusform>%n other transition: an upstream step is not active</numerusform>
            <numerusform>%n other transitions: an upstream step is not active</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::StepItem</name>
    <message numerus="yes">
        <source>Has a nested GRAFCET (%n steps)</source>
        <translation>
            <numerusform>Has a nested GRAFCET (%n step)</numerusform>
            <numerusform>Has a nested GRAFCET (%n steps)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Its nested GRAFCET has %n problems</source>
        <translation>
            <numerusform>Its nested GRAFCET has %n problem</numerusform>
            <numerusform>Its nested GRAFCET has %n problems</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::VariablesDock</name>
    <message numerus="yes">
        <source>Remove %n variables</source>
        <translation>
            <numerusform>Remove %n variable</numerusform>
            <numerusform>Remove %n variables</numerusform>
        </translation>
    </message>
</context>
</TS>
