<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>AddGrafcetActionCommand</name>
    <message>
        <source>Add action %1 to %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Aktion %1 zu Schritt %3 von %2 hinzufügen</translation>
    </message>
</context>
<context>
    <name>AddMachineComponentCommand</name>
    <message>
        <source>Add %1 %2</source>
        <extracomment>%1: a kind of machine component (&quot;Conveyor&quot;); %2: its name</extracomment>
        <translation>%1 %2 hinzufügen</translation>
    </message>
</context>
<context>
    <name>AddModeCommand</name>
    <message>
        <source>Add mode %1 %2</source>
        <translation>Betriebsart %1 %2 hinzufügen</translation>
    </message>
</context>
<context>
    <name>AddPropertyCommand</name>
    <message>
        <source>Add property</source>
        <translation>Eigenschaft hinzufügen</translation>
    </message>
</context>
<context>
    <name>AddVariableCommand</name>
    <message>
        <source>Add variable %1</source>
        <translation>Variable %1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>ChartExport</name>
    <message>
        <source>GEMMA-GRAFCET chart drawn by GG Studio</source>
        <translation>GEMMA-GRAFCET-Diagramm, gezeichnet mit GG Studio</translation>
    </message>
</context>
<context>
    <name>ConditionErrorText</name>
    <message>
        <source>comments are not allowed in a condition</source>
        <translation>Kommentare sind in einer Bedingung nicht erlaubt</translation>
    </message>
    <message>
        <source>use = to compare; := is assignment</source>
        <translation>= zum Vergleichen verwenden; := ist die Zuweisung</translation>
    </message>
    <message>
        <source>use = to compare; == is not Structured Text</source>
        <translation>= zum Vergleichen verwenden; == gibt es in Structured Text nicht</translation>
    </message>
    <message>
        <source>use &lt;&gt; for &apos;not equal&apos;</source>
        <translation>&lt;&gt; für &apos;ungleich&apos; verwenden</translation>
    </message>
    <message>
        <source>use NOT for negation</source>
        <translation>NOT für die Negation verwenden</translation>
    </message>
    <message>
        <source>use AND (or &amp;) for &apos;and&apos;</source>
        <translation>AND (oder &amp;) für &apos;und&apos; verwenden</translation>
    </message>
    <message>
        <source>use OR for &apos;or&apos;</source>
        <translation>OR für &apos;oder&apos; verwenden</translation>
    </message>
    <message>
        <source>&apos;**&apos; (power) is not supported in a condition</source>
        <translation>&apos;**&apos; (Potenz) wird in einer Bedingung nicht unterstützt</translation>
    </message>
    <message>
        <source>&apos;;&apos; is not allowed in a condition: write only the expression</source>
        <translation>&apos;;&apos; ist in einer Bedingung nicht erlaubt: nur den Ausdruck schreiben</translation>
    </message>
    <message>
        <source>the text contains bytes that are not valid UTF-8</source>
        <translation>der Text enthält Bytes, die kein gültiges UTF-8 sind</translation>
    </message>
    <message>
        <source>&apos;%1&apos; contains a non-ASCII character: names use ASCII letters, digits and _ only</source>
        <translation>&apos;%1&apos; enthält ein Nicht-ASCII-Zeichen: Namen bestehen nur aus ASCII-Buchstaben, Ziffern und _</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not supported: write plain decimal numbers, TRUE or FALSE (no typed, based or time literals)</source>
        <translation>&apos;%1&apos; wird nicht unterstützt: einfache Dezimalzahlen, TRUE oder FALSE schreiben (keine typisierten, Basis- oder Zeitliterale)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: qualified names are not allowed, write the variable name alone</source>
        <translation>&apos;%1&apos;: qualifizierte Namen sind nicht erlaubt, nur den Variablennamen schreiben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid number</source>
        <translation>&apos;%1&apos; ist keine gültige Zahl</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: write only the boolean expression, without IF ... THEN</source>
        <extracomment>%1: IF, THEN, ELSE... as written</extracomment>
        <translation>&apos;%1&apos; ist in einer Bedingung nicht erlaubt: nur den booleschen Ausdruck schreiben, ohne IF ... THEN</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: it is a type name</source>
        <translation>&apos;%1&apos; ist in einer Bedingung nicht erlaubt: Es ist ein Typname</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: it is an IEC 61131-3 keyword</source>
        <translation>&apos;%1&apos; ist in einer Bedingung nicht erlaubt: Es ist ein Schlüsselwort von IEC 61131-3</translation>
    </message>
    <message>
        <source>unexpected control character (byte %1)</source>
        <extracomment>%1: the byte in hexadecimal (0x1B)</extracomment>
        <translation>unerwartetes Steuerzeichen (Byte %1)</translation>
    </message>
    <message>
        <source>unexpected character &apos;%1&apos;</source>
        <translation>unerwartetes Zeichen &apos;%1&apos;</translation>
    </message>
    <message>
        <source>condition too complex: operators nested more than %1 levels deep</source>
        <translation>Bedingung zu komplex: Operatoren über mehr als %1 Ebenen verschachtelt</translation>
    </message>
    <message>
        <source>condition nested too deeply: more than %1 levels of parentheses</source>
        <translation>Bedingung zu tief verschachtelt: mehr als %1 Klammerebenen</translation>
    </message>
    <message>
        <source>condition nested too deeply: more than %1 levels of unary operators</source>
        <translation>Bedingung zu tief verschachtelt: mehr als %1 Ebenen unärer Operatoren</translation>
    </message>
    <message>
        <source>unmatched &apos;)&apos;: no &apos;(&apos; opens it</source>
        <translation>&apos;)&apos; ohne Gegenstück: Keine &apos;(&apos; öffnet sie</translation>
    </message>
    <message>
        <source>expected an operand before &apos;%1&apos;</source>
        <extracomment>%1: an operator the condition starts with</extracomment>
        <translation>Operand vor &apos;%1&apos; erwartet</translation>
    </message>
    <message>
        <source>empty parentheses: expected an expression inside &apos;( )&apos;</source>
        <translation>leere Klammern: Ausdruck in &apos;( )&apos; erwartet</translation>
    </message>
    <message>
        <source>expected an operand after &apos;%1&apos;</source>
        <extracomment>%1: the operator or &apos;(&apos; the condition ends with</extracomment>
        <translation>Operand nach &apos;%1&apos; erwartet</translation>
    </message>
    <message>
        <source>expected an operand after &apos;%1&apos;, found &apos;%2&apos;</source>
        <extracomment>%1: an operator or &apos;(&apos;; %2: what follows it instead of an operand</extracomment>
        <translation>Operand nach &apos;%1&apos; erwartet, &apos;%2&apos; gefunden</translation>
    </message>
    <message>
        <source>unmatched &apos;(&apos; at column %1: missing &apos;)&apos;</source>
        <extracomment>%1: a column number</extracomment>
        <translation>&apos;(&apos; ohne Gegenstück in Spalte %1: &apos;)&apos; fehlt</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos;: expected an operator or &apos;)&apos; to close the &apos;(&apos; at column %2</source>
        <extracomment>%1: what was found; %2: the column of the &apos;(&apos;</extracomment>
        <translation>unerwartetes &apos;%1&apos;: Operator oder &apos;)&apos; erwartet, um die &apos;(&apos; in Spalte %2 zu schließen</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete condition</source>
        <translation>unerwartetes &apos;%1&apos; nach einer vollständigen Bedingung</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete condition (missing operator?)</source>
        <translation>unerwartetes &apos;%1&apos; nach einer vollständigen Bedingung (fehlt ein Operator?)</translation>
    </message>
    <message>
        <source>an edge (RE, FE, ↑, ↓) applies to a variable name</source>
        <translation>eine Flanke (RE, FE, ↑, ↓) gilt für einen Variablennamen</translation>
    </message>
    <message>
        <source>an edge (RE, FE, ↑, ↓) applies to a variable name, not to &apos;%1&apos;</source>
        <extracomment>%1: what follows RE, FE, ↑ or ↓ instead of a variable name</extracomment>
        <translation>eine Flanke (RE, FE, ↑, ↓) gilt für einen Variablennamen, nicht für „%1“</translation>
    </message>
    <message>
        <source>the duration &apos;%1&apos; must be followed by /X&lt;step&gt;, as in %1/X3</source>
        <extracomment>%1: a duration such as 5s; X3 is step 3&apos;s activity, keep it as is</extracomment>
        <translation>auf die Dauer „%1“ muss /X&lt;Schritt&gt; folgen, wie in %1/X3</translation>
    </message>
    <message>
        <source>expected a step activity X&lt;step&gt; after &apos;/&apos; of the duration</source>
        <translation>nach dem „/“ der Dauer wird eine Schrittaktivität X&lt;Schritt&gt; erwartet</translation>
    </message>
    <message>
        <source>expected a step activity X&lt;step&gt; after &apos;/&apos; of the duration, found &apos;%1&apos;</source>
        <translation>nach dem „/“ der Dauer wird eine Schrittaktivität X&lt;Schritt&gt; erwartet, gefunden: „%1“</translation>
    </message>
    <message>
        <source>the duration &apos;%1&apos; is zero: write a positive duration</source>
        <translation>die Dauer „%1“ ist null: schreiben Sie eine positive Dauer</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid duration: write for example 200ms, 5s, 1m30s or T#5s (units d, h, m, s, ms, largest first)</source>
        <translation>„%1“ ist keine gültige Dauer: schreiben Sie zum Beispiel 200ms, 5s, 1m30s oder T#5s (Einheiten d, h, m, s, ms, die größte zuerst)</translation>
    </message>
    <message>
        <source>empty action: write for example Valve, S Valve, R Valve or Count := Count + 1</source>
        <translation>leere Aktion: schreiben Sie zum Beispiel Valve, S Valve, R Valve oder Count := Count + 1</translation>
    </message>
    <message>
        <source>an action writes a variable: &apos;%1&apos; is not a variable name</source>
        <translation>eine Aktion schreibt eine Variable: „%1“ ist kein Variablenname</translation>
    </message>
    <message>
        <source>the qualifier &apos;%1&apos; is not supported: use N (or none), S, R or an assignment V := value</source>
        <translation>der Bestimmungszeichen „%1“ wird nicht unterstützt: verwenden Sie N (oder keines), S, R oder eine Zuweisung V := Wert</translation>
    </message>
    <message>
        <source>an assignment takes no qualifier: write V := value, without &apos;%1&apos;</source>
        <translation>eine Zuweisung hat kein Bestimmungszeichen: schreiben Sie V := Wert, ohne „%1“</translation>
    </message>
    <message>
        <source>a stored action (%1) takes no IF condition: only continuous actions are conditional</source>
        <extracomment>%1: the qualifier S or R</extracomment>
        <translation>eine speichernde Aktion (%1) hat keine IF-Bedingung: nur kontinuierliche Aktionen sind bedingt</translation>
    </message>
    <message>
        <source>expected a value after &apos;:=&apos;</source>
        <translation>nach „:=“ wird ein Wert erwartet</translation>
    </message>
    <message>
        <source>expected a condition after IF</source>
        <translation>nach IF wird eine Bedingung erwartet</translation>
    </message>
    <message>
        <source>use := to assign a value; = compares</source>
        <translation>verwenden Sie := für eine Zuweisung; = vergleicht</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete action</source>
        <translation>unerwartetes „%1“ nach einer vollständigen Aktion</translation>
    </message>
    <message>
        <source>empty condition: write when the transition fires (TRUE if it is always ready), or hide the transition if the machine does not need it</source>
        <translation>leere Bedingung: schreiben Sie, wann die Transition schaltet (TRUE, wenn sie immer bereit ist), oder blenden Sie die Transition aus, wenn die Maschine sie nicht braucht</translation>
    </message>
    <message>
        <source>a property starts with never or always</source>
        <translation>eine Eigenschaft beginnt mit never oder always</translation>
    </message>
    <message>
        <source>a property starts with never or always, not &apos;%1&apos;</source>
        <translation>eine Eigenschaft beginnt mit never oder always, nicht mit &apos;%1&apos;</translation>
    </message>
    <message>
        <source>expected a GEMMA step after &apos;in&apos;</source>
        <translation>nach &apos;in&apos; wird ein GEMMA-Schritt erwartet</translation>
    </message>
    <message>
        <source>expected a GEMMA step after &apos;in&apos;, found &apos;%1&apos;</source>
        <translation>nach &apos;in&apos; wird ein GEMMA-Schritt erwartet, gefunden: &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>ConditionTypeErrorText</name>
    <message>
        <source>&apos;%1&apos; is an integer</source>
        <extracomment>%1: a subexpression of the condition</extracomment>
        <translation>&apos;%1&apos; ist eine ganze Zahl</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a real number</source>
        <translation>&apos;%1&apos; ist eine reelle Zahl</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is of unknown type</source>
        <translation>&apos;%1&apos; ist von unbekanntem Typ</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is %2</source>
        <extracomment>%1: a subexpression of the condition; %2: its IEC type (INT, BOOL)</extracomment>
        <translation>&apos;%1&apos; ist vom Typ %2</translation>
    </message>
    <message>
        <source>a condition must be BOOL, but %1</source>
        <extracomment>%1: the condition and what it is (&quot;&apos;Speed + 1&apos; is an integer&quot;)</extracomment>
        <translation>eine Bedingung muss BOOL sein, aber %1</translation>
    </message>
    <message>
        <source>%1 needs a BOOL operand, but %2</source>
        <extracomment>%1: NOT; %2: its operand and what it is (&quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 erfordert einen BOOL-Operanden, aber %2</translation>
    </message>
    <message>
        <source>unary %1 needs a numeric operand, but %2</source>
        <extracomment>%1: &apos;-&apos; (negation); %2: its operand and what it is (&quot;&apos;Start&apos; is BOOL&quot;)</extracomment>
        <translation>das unäre %1 erfordert einen numerischen Operanden, aber %2</translation>
    </message>
    <message>
        <source>%1 needs BOOL operands, but %2</source>
        <extracomment>%1: AND, OR or XOR; %2: the operand at fault and what it is (&quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 erfordert BOOL-Operanden, aber %2</translation>
    </message>
    <message>
        <source>%1 needs numeric operands, but %2</source>
        <extracomment>%1: a comparison or arithmetic operator (&apos;&lt;&apos;, &apos;+&apos;); %2: the operand at fault and what it is</extracomment>
        <translation>%1 erfordert numerische Operanden, aber %2</translation>
    </message>
    <message>
        <source>%1 needs integer operands, but %2</source>
        <extracomment>%1: MOD; %2: the operand at fault and what it is (&quot;&apos;Temp&apos; is REAL&quot;)</extracomment>
        <translation>%1 erfordert ganzzahlige Operanden, aber %2</translation>
    </message>
    <message>
        <source>%1 needs two operands of the same kind, but %2 and %3</source>
        <extracomment>%1: &apos;=&apos; or &apos;&lt;&gt;&apos;; %2, %3: each operand and what it is (&quot;&apos;Start&apos; is BOOL&quot;, &quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 erfordert zwei Operanden derselben Art, aber %2 und %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range: integer literals go up to 9223372036854775807 (LINT)</source>
        <translation>&apos;%1&apos; liegt außerhalb des Wertebereichs: Ganzzahlliterale reichen bis 9223372036854775807 (LINT)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range for LREAL (-1.8E308..1.8E308)</source>
        <translation>&apos;%1&apos; liegt außerhalb des Wertebereichs von LREAL (-1.8E308..1.8E308)</translation>
    </message>
</context>
<context>
    <name>ConveyorItem</name>
    <message>
        <source>Parts out: %1</source>
        <translation>Ausgegebene Teile: %1</translation>
    </message>
</context>
<context>
    <name>DeclarationFixText</name>
    <message>
        <source>Declare &apos;%1&apos; as OUTPUT %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>&apos;%1&apos; als Ausgang %2 deklarieren</translation>
    </message>
    <message>
        <source>Declare &apos;%1&apos; as INTERNAL %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>&apos;%1&apos; als interne Variable %2 deklarieren</translation>
    </message>
    <message>
        <source>Declare &apos;%1&apos; as INPUT %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>&apos;%1&apos; als Eingang %2 deklarieren</translation>
    </message>
</context>
<context>
    <name>DiagnosticText</name>
    <message>
        <source>the name is empty</source>
        <translation>der Name ist leer</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid IEC 61131-3 identifier: use ASCII letters, digits and &apos;_&apos;, not starting with a digit</source>
        <translation>&apos;%1&apos; ist kein gültiger Bezeichner nach IEC 61131-3: ASCII-Buchstaben, Ziffern und &apos;_&apos; verwenden, nicht mit einer Ziffer beginnen</translation>
    </message>
    <message>
        <source>&apos;%1&apos; contains &apos;__&apos;, which IEC 61131-3 identifiers may not</source>
        <translation>&apos;%1&apos; enthält &apos;__&apos;, was in Bezeichnern nach IEC 61131-3 nicht erlaubt ist</translation>
    </message>
    <message>
        <source>&apos;%1&apos; ends with &apos;_&apos;, which IEC 61131-3 identifiers may not</source>
        <translation>&apos;%1&apos; endet mit &apos;_&apos;, was in Bezeichnern nach IEC 61131-3 nicht erlaubt ist</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is an IEC 61131-3 keyword or type name</source>
        <translation>&apos;%1&apos; ist ein Schlüsselwort oder Typname von IEC 61131-3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a name the generated code uses</source>
        <translation>&apos;%1&apos; ist ein Name, den der generierte Code verwendet</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; does not occur in the condition.</source>
        <translation>Der Merker auf &apos;%2&apos; in %1 ist ungültig: &apos;%2&apos; kommt in der Bedingung nicht vor.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is ambiguous: the condition uses both %2 and NOT %2, so the token could be neither normally open nor normally closed.</source>
        <translation>Der Merker auf &apos;%2&apos; in %1 ist mehrdeutig: Die Bedingung verwendet sowohl %2 als auch NOT %2, daher kann der Merker weder Schließer noch Öffner sein.</translation>
    </message>
    <message>
        <source>The token in %1 names &apos;%2&apos;, which is not a declared variable.</source>
        <translation>Der Merker in %1 nennt &apos;%2&apos;, das keine deklarierte Variable ist.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; is compared with &apos;=&apos; or &apos;&lt;&gt;&apos; in the condition, where it has no polarity; a token can only replace a literal %2 or NOT %2.</source>
        <translation>Der Merker auf &apos;%2&apos; in %1 ist ungültig: &apos;%2&apos; wird in der Bedingung mit &apos;=&apos; oder &apos;&lt;&gt;&apos; verglichen und hat dort keine Polarität; ein Merker kann nur ein Literal %2 oder NOT %2 ersetzen.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 has no effect and is not generated: family transitions never wait for Complete.</source>
        <translation>Der Merker auf &apos;%2&apos; in %1 ist wirkungslos und wird nicht generiert: Familientransitionen warten nie auf Complete.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 has no effect and is not generated: its source %3 is a simple step.</source>
        <translation>Der Merker auf &apos;%2&apos; in %1 ist wirkungslos und wird nicht generiert: Sein Quellschritt %3 ist ein einfacher Schritt.</translation>
    </message>
    <message>
        <source>The initial step %1 is hidden: the PLC would start in a state that has no code.</source>
        <translation>Der Anfangsschritt %1 ist ausgeblendet: Die SPS würde in einem Zustand ohne Code starten.</translation>
    </message>
    <message>
        <source>Step %1 has no visible outgoing transition: the machine would stay in it forever.</source>
        <translation>Schritt %1 hat keine sichtbare ausgehende Transition: Die Maschine bliebe für immer darin.</translation>
    </message>
    <message>
        <source>Step %1 has no visible incoming transition: it can never become active.</source>
        <translation>Schritt %1 hat keine sichtbare eingehende Transition: Er kann nie aktiv werden.</translation>
    </message>
    <message>
        <source>The family transition %1 is negated, which has no effect: family transitions never wait for Complete.</source>
        <translation>Die Familientransition %1 ist negiert, was wirkungslos ist: Familientransitionen warten nie auf Complete.</translation>
    </message>
    <message>
        <source>The condition of %1 is FALSE: the transition can never fire (hide it instead).</source>
        <translation>Die Bedingung von %1 ist FALSE: Die Transition kann nie schalten (besser ausblenden).</translation>
    </message>
    <message>
        <source>Step %1 cannot be reached from the initial step %2 through visible transitions: it can never become active.</source>
        <translation>Schritt %1 ist vom Anfangsschritt %2 aus über sichtbare Transitionen nicht erreichbar: Er kann nie aktiv werden.</translation>
    </message>
    <message>
        <source>Transition %1 is negated, which has no effect: its source %2 is a simple step, and negation only changes transitions out of macro and enclosing steps.</source>
        <translation>Transition %1 ist negiert, was wirkungslos ist: Ihr Quellschritt %2 ist ein einfacher Schritt, und die Negation ändert nur Transitionen aus Makroschritten und einschließenden Schritten.</translation>
    </message>
    <message>
        <source>The condition of %1 is TRUE and does not wait for Complete: the lower-priority transitions %2 can never fire.</source>
        <translation>Die Bedingung von %1 ist TRUE und wartet nicht auf Complete: Die Transitionen niedrigerer Priorität %2 können nie schalten.</translation>
    </message>
    <message>
        <source>Invalid variable name: %1.</source>
        <translation>Ungültiger Variablenname: %1.</translation>
    </message>
    <message>
        <source>Syntax error in the condition of %1: %2.</source>
        <translation>Syntaxfehler in der Bedingung von %1: %2.</translation>
    </message>
    <message>
        <source>In the condition of %1: &apos;%2&apos; is not a declared variable.</source>
        <translation>In der Bedingung von %1: &apos;%2&apos; ist keine deklarierte Variable.</translation>
    </message>
    <message>
        <source>Type error in the condition of %1: %2.</source>
        <translation>Typfehler in der Bedingung von %1: %2.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; is %3, and only BOOL variables can have a token.</source>
        <translation>Der Merker auf &apos;%2&apos; in %1 ist ungültig: &apos;%2&apos; hat den Typ %3, und nur BOOL-Variablen können einen Merker haben.</translation>
    </message>
    <message>
        <source>The default value of variable &apos;%1&apos; is invalid: %2.</source>
        <translation>Der Anfangswert der Variablen &apos;%1&apos; ist ungültig: %2.</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Information</source>
        <translation>Information</translation>
    </message>
    <message>
        <source>The verification reached its time or size limit before every property was decided: the properties not reported were not decided.</source>
        <translation>Die Verifikation hat ihre Zeit- oder Größengrenze erreicht, bevor alle Eigenschaften entschieden waren: Nicht gemeldete Eigenschaften wurden nicht entschieden.</translation>
    </message>
    <message>
        <source>The verification reached its time or size limit before deciding everything about %1: what is not reported about it was not decided. Every other finding holds.</source>
        <translation>Die Verifikation hat ihre Zeit- oder Größengrenze erreicht, bevor alles über %1 entschieden war: Was dazu nicht gemeldet wird, wurde nicht entschieden. Alle anderen Befunde gelten.</translation>
    </message>
    <message>
        <source>Step %1 can never become active: no effective transition leads to it.</source>
        <translation>Schritt %1 kann nie aktiv werden: Keine wirksame Transition führt zu ihm.</translation>
    </message>
    <message>
        <source>Step %1 can never become active: no situation reachable from the initial step lets %2 fire.</source>
        <translation>Schritt %1 kann nie aktiv werden: In keiner vom Anfangsschritt aus erreichbaren Situation kann %2 schalten.</translation>
    </message>
    <message>
        <source>Transition %1 can never fire: its condition is never TRUE in a situation reachable from the initial step.</source>
        <translation>Transition %1 kann nie schalten: Ihre Bedingung ist in keiner vom Anfangsschritt aus erreichbaren Situation TRUE.</translation>
    </message>
    <message>
        <source>Transition %1 can never fire: whenever its condition holds, a transition of higher priority fires first (%2).</source>
        <translation>Transition %1 kann nie schalten: Immer wenn ihre Bedingung erfüllt ist, schaltet zuerst eine Transition höherer Priorität (%2).</translation>
    </message>
    <message>
        <source>The condition of %1 is always TRUE: no own transition of an F step can ever fire.</source>
        <translation>Die Bedingung von %1 ist immer TRUE: Keine eigene Transition eines F-Schritts kann je schalten.</translation>
    </message>
    <message>
        <source>The condition of %1 is always TRUE when %3 is active: %2 can never fire.</source>
        <translation>Die Bedingung von %1 ist immer TRUE, wenn %3 aktiv ist: %2 kann nie schalten.</translation>
    </message>
    <message>
        <source>%1 and %2 can both be TRUE in the same scan: the priority decides, %1 fires.</source>
        <translation>%1 und %2 können im selben Zyklus beide TRUE sein: Die Priorität entscheidet, %1 schaltet.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead to a situation from which the initial step can never become active again.</source>
        <translation>Ist %1 aktiv, können die Eingänge zu einer Situation führen, aus der der Anfangsschritt nie wieder aktiv werden kann.</translation>
    </message>
    <message>
        <source>Step %1 can get stuck: the inputs can lead to a situation in it from which no transition out of it can ever fire.</source>
        <translation>Schritt %1 kann hängen bleiben: Die Eingänge können zu einer Situation darin führen, in der keine seiner ausgehenden Transitionen je schalten kann.</translation>
    </message>
    <message>
        <source>The emergency stop D1 can never be entered from %1: the family transition F-&gt;D1 is not effective and %1 has no transition to D1.</source>
        <translation>Der Not-Halt D1 kann von %1 aus nie erreicht werden: Die Familientransition F-&gt;D1 ist nicht wirksam und %1 hat keine Transition nach D1.</translation>
    </message>
    <message>
        <source>In some situations of %1 the emergency stop D1 cannot be entered in one scan, whatever the inputs: %2 cannot fire there.</source>
        <translation>In manchen Situationen von %1 kann der Not-Halt D1 nicht in einem Zyklus erreicht werden, was auch immer die Eingänge sind: %2 kann dort nicht schalten.</translation>
    </message>
    <message>
        <source>Not confirmed: a condition uses a comparison the verifier cannot decide, and the counterexample does not replay.</source>
        <translation>Nicht bestätigt: Eine Bedingung verwendet einen Vergleich, den der Verifizierer nicht entscheiden kann, und das Gegenbeispiel lässt sich nicht abspielen.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 has no initial step: it would never do anything.</source>
        <translation>Der eingebettete GRAFCET von %1 hat keinen Anfangsschritt: er würde nie etwas tun.</translation>
    </message>
    <message>
        <source>Step %2 of %1 cannot be reached from the initial steps through transitions: it can never become active.</source>
        <translation>Schritt %2 von %1 ist von den Anfangsschritten über Transitionen nicht erreichbar: er kann nie aktiv werden.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 never sets Complete, so %2, which wait for it, can never fire.</source>
        <extracomment>%2: the GEMMA transitions that wait for Complete</extracomment>
        <translation>Der eingebettete GRAFCET von %1 setzt Complete nie, daher können %2, die darauf warten, nie schalten.</translation>
    </message>
    <message>
        <source>The selection after step %2 of %1 is not exclusive: %3 and %4 can both fire (with %5), and both branches then start.</source>
        <extracomment>%3, %4: two nested transitions; %5: the values that make both receptivities TRUE</extracomment>
        <translation>Die Auswahl nach Schritt %2 von %1 ist nicht exklusiv: %3 und %4 können gleichzeitig schalten (mit %5), und dann starten beide Zweige.</translation>
    </message>
    <message>
        <source>Step %2 of %1 has no outgoing transition and does not set Complete: the GRAFCET stops there for good.</source>
        <translation>Schritt %2 von %1 hat keine nachfolgende Transition und setzt Complete nicht: der GRAFCET bleibt dort für immer stehen.</translation>
    </message>
    <message>
        <source>Under the until-stable rule, step %2 of %1 is left in the call that enters it (%3 is always TRUE): the GEMMA layer never sees what it does to Complete.</source>
        <translation>Nach der Regel „bis stabil“ wird Schritt %2 von %1 im selben Aufruf verlassen, der ihn aktiviert (%3 ist immer wahr): die GEMMA-Ebene sieht nie, was er mit Complete macht.</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has a name the code of the nested GRAFCETs uses: %2.</source>
        <extracomment>%2: why, in English (a technical reason)</extracomment>
        <translation>Die Variable „%1“ hat einen Namen, den der Code der eingebetteten GRAFCETs verwendet: %2.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 is kept but not used: %1 is hidden.</source>
        <translation>Der eingebettete GRAFCET von %1 bleibt erhalten, wird aber nicht verwendet: %1 ist ausgeblendet.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 is kept but not used: %1 is a simple step.</source>
        <translation>Der eingebettete GRAFCET von %1 bleibt erhalten, wird aber nicht verwendet: %1 ist ein einfacher Schritt.</translation>
    </message>
    <message>
        <source>The condition of %1 is empty: write when it fires (TRUE if it is always ready), or hide the transition if your machine does not need it.</source>
        <translation>Die Bedingung von %1 ist leer: Schreiben Sie, wann sie schaltet (TRUE, wenn sie immer bereit ist), oder blenden Sie die Transition aus, wenn Ihre Maschine sie nicht braucht.</translation>
    </message>
    <message>
        <source>Step %2 of the nested GRAFCET of %1 can never become active.</source>
        <extracomment>%1: a GEMMA step; %2: the number of a step of its nested GRAFCET</extracomment>
        <translation>Schritt %2 des eingebetteten GRAFCET von %1 kann nie aktiv werden.</translation>
    </message>
    <message>
        <source>Transition T%2 of the nested GRAFCET of %1 can never fire.</source>
        <extracomment>%1: a GEMMA step; %2: the number of a transition of its nested GRAFCET</extracomment>
        <translation>Transition T%2 des eingebetteten GRAFCET von %1 kann nie schalten.</translation>
    </message>
    <message>
        <source>Step %2 of the nested GRAFCET of %1 can be activated while it is already active: the GRAFCET is not safe.</source>
        <translation>Schritt %2 des eingebetteten GRAFCET von %1 kann aktiviert werden, während er schon aktiv ist: der GRAFCET ist nicht sicher.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 can be Unstable: its evolutions do not settle within one scan.</source>
        <translation>Der eingebettete GRAFCET von %1 kann instabil sein (Unstable): seine Entwicklungen kommen in einem Zyklus nicht zur Ruhe.</translation>
    </message>
    <message>
        <source>Transitions T%3 and T%4 of the nested GRAFCET of %1 can fire together from step %2: both branches of the selection start.</source>
        <extracomment>%2: a nested step; %3, %4: the numbers of two nested transitions</extracomment>
        <translation>Die Transitionen T%3 und T%4 des eingebetteten GRAFCET von %1 können gemeinsam aus Schritt %2 schalten: beide Zweige der Auswahl starten.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead its nested GRAFCET to a situation from which Complete never becomes TRUE.</source>
        <translation>Ist %1 aktiv, können die Eingänge seinen eingebetteten GRAFCET in eine Situation führen, aus der Complete nie TRUE wird.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead its nested GRAFCET to a situation from which Complete never becomes TRUE: %2 can no longer fire.</source>
        <extracomment>%2: the GEMMA transitions that wait for Complete</extracomment>
        <translation>Ist %1 aktiv, können die Eingänge seinen eingebetteten GRAFCET in eine Situation führen, aus der Complete nie TRUE wird: %2 kann nicht mehr schalten.</translation>
    </message>
    <message>
        <source>%1 waits for the Complete of %2, which never becomes TRUE: it can never fire.</source>
        <translation>%1 wartet auf das Complete von %2, das nie TRUE wird: sie kann nie schalten.</translation>
    </message>
    <message>
        <source>Steps %2 and %3 of the nested GRAFCET of %1 can write different values to &apos;%4&apos; in the same scan: the result depends on the order of the actions.</source>
        <translation>Die Schritte %2 und %3 des eingebetteten GRAFCET von %1 können im selben Zyklus verschiedene Werte in &apos;%4&apos; schreiben: das Ergebnis hängt von der Reihenfolge der Aktionen ab.</translation>
    </message>
    <message>
        <source>The continuous output &apos;%2&apos; can still be TRUE in the scan in which the emergency stop %1 is entered.</source>
        <translation>Der kontinuierliche Ausgang &apos;%2&apos; kann in dem Zyklus, in dem der Not-Halt %1 betreten wird, noch TRUE sein.</translation>
    </message>
    <message>
        <source>The stored output &apos;%2&apos; can still be TRUE in the scan in which the emergency stop %1 is entered: stored actions are memories, only continuous outputs drop with the state.</source>
        <translation>Der gespeicherte Ausgang &apos;%2&apos; kann in dem Zyklus, in dem der Not-Halt %1 betreten wird, noch TRUE sein: gespeicherte Aktionen sind Speicher, nur kontinuierliche Ausgänge fallen mit dem Zustand ab.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; does not hold.</source>
        <translation>Die Eigenschaft &apos;%1&apos; gilt nicht.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; holds in every reachable scan, with the abstractions the verification lists.</source>
        <translation>Die Eigenschaft &apos;%1&apos; gilt in jedem erreichbaren Zyklus, mit den Abstraktionen, die die Verifikation nennt.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; holds in every reachable scan.</source>
        <translation>Die Eigenschaft &apos;%1&apos; gilt in jedem erreichbaren Zyklus.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; cannot be checked: it is empty.</source>
        <translation>Die Eigenschaft &apos;%1&apos; kann nicht geprüft werden: sie ist leer.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; cannot be checked: %2.</source>
        <extracomment>%2: why, in English (the property checker&apos;s message)</extracomment>
        <translation>Die Eigenschaft &apos;%1&apos; kann nicht geprüft werden: %2.</translation>
    </message>
    <message>
        <source>The exploration of both layers reached its time or size limit: what it found is reported, but nothing about the nested GRAFCETs or the properties is proved.</source>
        <translation>Die Erkundung beider Ebenen hat ihre Zeit- oder Größengrenze erreicht: was sie fand, wird gemeldet, aber über die eingebetteten GRAFCETs und die Eigenschaften ist nichts bewiesen.</translation>
    </message>
    <message>
        <source>Not confirmed: the run found under the abstractions of the verification does not replay in the simulator.</source>
        <translation>Nicht bestätigt: der unter den Abstraktionen der Verifikation gefundene Ablauf lässt sich im Simulator nicht nachspielen.</translation>
    </message>
    <message>
        <source>Not confirmed: decided on the GEMMA layer with every Complete free, and the run does not replay with the nested GRAFCETs.</source>
        <translation>Nicht bestätigt: auf der GEMMA-Ebene mit jedem Complete frei entschieden, und der Ablauf lässt sich mit den verschachtelten GRAFCETs nicht nachspielen.</translation>
    </message>
    <message>
        <source>In the condition of %1: &apos;%2&apos; divides by zero: on the PLC an integer division or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / 0)</extracomment>
        <translation>In der Bedingung von %1: &apos;%2&apos; teilt durch null: in der SPS hält eine ganzzahlige Division oder ein MOD durch null die Task mit einem Fehler an, eine REAL-Division ergibt INF oder NaN.</translation>
    </message>
    <message>
        <source>In the condition of %1: the divisor of &apos;%2&apos; can be zero: an integer division or MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / Batch)</extracomment>
        <translation>In der Bedingung von %1: der Divisor von &apos;%2&apos; kann null sein: eine ganzzahlige Division oder ein MOD durch null hält die SPS mit einem Fehler an (und die Simulation), eine REAL-Division ergibt INF oder NaN.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; is undecided: neither proved nor shown violated (%2).</source>
        <extracomment>%2: why, in English (the verifier&apos;s reason)</extracomment>
        <translation>Die Eigenschaft &apos;%1&apos; ist unentschieden: weder bewiesen noch als verletzt gezeigt (%2).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the function block of enclosing step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>Die Variable &apos;%1&apos; trägt den Namen des Funktionsbausteins des einschließenden Schritts %2 im erzeugten Code: benennen Sie die Variable um (zum Beispiel in &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the function block of macro-step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>Die Variable &apos;%1&apos; trägt den Namen des Funktionsbausteins des Makroschritts %2 im erzeugten Code: benennen Sie die Variable um (zum Beispiel in &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the instance of enclosing step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>Die Variable &apos;%1&apos; trägt den Namen der Instanz des einschließenden Schritts %2 im erzeugten Code: benennen Sie die Variable um (zum Beispiel in &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the instance of macro-step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>Die Variable &apos;%1&apos; trägt den Namen der Instanz des Makroschritts %2 im erzeugten Code: benennen Sie die Variable um (zum Beispiel in &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Enclosing step %1 declares its function block %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>Der einschließende Schritt %1 deklariert seinen Funktionsbaustein %2 im erzeugten Code, und die Variable &apos;%3&apos; trägt diesen Namen: benennen Sie die Variable um (zum Beispiel in &apos;%4&apos;) oder machen Sie %1 zu einem einfachen Schritt.</translation>
    </message>
    <message>
        <source>Macro-step %1 declares its function block %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>Der Makroschritt %1 deklariert seinen Funktionsbaustein %2 im erzeugten Code, und die Variable &apos;%3&apos; trägt diesen Namen: benennen Sie die Variable um (zum Beispiel in &apos;%4&apos;) oder machen Sie %1 zu einem einfachen Schritt.</translation>
    </message>
    <message>
        <source>Enclosing step %1 declares its instance %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>Der einschließende Schritt %1 deklariert seine Instanz %2 im erzeugten Code, und die Variable &apos;%3&apos; trägt diesen Namen: benennen Sie die Variable um (zum Beispiel in &apos;%4&apos;) oder machen Sie %1 zu einem einfachen Schritt.</translation>
    </message>
    <message>
        <source>Macro-step %1 declares its instance %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>Der Makroschritt %1 deklariert seine Instanz %2 im erzeugten Code, und die Variable &apos;%3&apos; trägt diesen Namen: benennen Sie die Variable um (zum Beispiel in &apos;%4&apos;) oder machen Sie %1 zu einem einfachen Schritt.</translation>
    </message>
    <message>
        <source>%2 is read in %3 and by its level in %4, which can fire right after it: while %2 stays TRUE, both fire in the same scan and step %5 of %1 is passed through; read its rising edge in %4 (↑%2) so that each press fires one transition.</source>
        <extracomment>%2: a BOOL input; %3, %4: two nested transitions; %5: the steps between them</extracomment>
        <translation>%2 wird in %3 und über seinen Pegel in %4 gelesen, die direkt danach schalten kann: solange %2 TRUE bleibt, schalten beide im selben Zyklus und Schritt %5 von %1 wird durchlaufen; lesen Sie in %4 die steigende Flanke (↑%2), damit jeder Tastendruck genau eine Transition schaltet.</translation>
    </message>
    <message>
        <source>%2 is read in %3 and by its level in %4, which can fire right after it: while %2 stays TRUE, both fire in consecutive scans and step %5 of %1 is passed through; read its rising edge in %4 (↑%2) so that each press fires one transition.</source>
        <translation>%2 wird in %3 und über seinen Pegel in %4 gelesen, die direkt danach schalten kann: solange %2 TRUE bleibt, schalten beide in aufeinanderfolgenden Zyklen und Schritt %5 von %1 wird durchlaufen; lesen Sie in %4 die steigende Flanke (↑%2), damit jeder Tastendruck genau eine Transition schaltet.</translation>
    </message>
    <message>
        <source>The selection after step %2 of %1 is not complete: with %4 none of %3 fires and the GRAFCET waits in step %2; add a branch for these values unless waiting is intended.</source>
        <extracomment>%3: the branches (T1, T2); %4: values of the variables (CP1 = TRUE, CP2 = FALSE)</extracomment>
        <translation>Die Auswahl nach Schritt %2 von %1 ist nicht vollständig: mit %4 schaltet keine von %3, und der GRAFCET wartet in Schritt %2; fügen Sie einen Zweig für diese Werte hinzu, sofern das Warten nicht gewollt ist.</translation>
    </message>
    <message>
        <source>Not confirmed: its counterexample does not replay to it in the simulator.</source>
        <translation>Nicht bestätigt: Sein Gegenbeispiel führt im Simulator nicht dorthin.</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; is used by no condition, receptivity or action that generates code.</source>
        <translation>Die Variable &apos;%1&apos; wird von keiner Bedingung, Weiterschaltbedingung oder Aktion verwendet, die Code erzeugt.</translation>
    </message>
    <message>
        <source>Not confirmed: the run found under the abstractions of the verification does not replay in the simulator, and the search for one with time counted in scans stopped at the time or size limit (a longer time limit may find it).</source>
        <translation>Nicht bestätigt: der unter den Abstraktionen der Verifikation gefundene Ablauf lässt sich im Simulator nicht nachspielen, und die Suche nach einem Ablauf mit in Zyklen gezählter Zeit hat an der Zeit- oder Größengrenze angehalten (eine längere Zeitgrenze kann ihn finden).</translation>
    </message>
</context>
<context>
    <name>EditMachineComponentCommand</name>
    <message>
        <source>Edit %1</source>
        <translation>%1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>ElementLabels</name>
    <message>
        <source>F (family)</source>
        <translation>F (Familie)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <extracomment>a transition: source step, arrow, target step</extracomment>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Simple step</source>
        <translation>Einfacher Schritt</translation>
    </message>
    <message>
        <source>Macro-step</source>
        <translation>Makroschritt</translation>
    </message>
    <message>
        <source>Enclosing step</source>
        <translation>Einschließender Schritt</translation>
    </message>
    <message>
        <source>hidden</source>
        <translation>ausgeblendet</translation>
    </message>
    <message>
        <source>source %1 hidden</source>
        <translation>Quellschritt %1 ausgeblendet</translation>
    </message>
    <message>
        <source>target %1 hidden</source>
        <translation>Zielschritt %1 ausgeblendet</translation>
    </message>
</context>
<context>
    <name>ExampleModels</name>
    <message>
        <source>Drilling Cell</source>
        <translation>Bohrzelle</translation>
    </message>
    <message>
        <source>A machine that clamps, drills and marks parts: GEMMA states with four nested GRAFCETs, ready to simulate</source>
        <translation>Eine Maschine, die Teile spannt, bohrt und markiert: GEMMA-Zustände mit vier eingebetteten GRAFCETs, bereit zur Simulation</translation>
    </message>
    <message>
        <source>Drilling Cell with Mistakes</source>
        <translation>Bohrzelle mit Fehlern</translation>
    </message>
    <message>
        <source>The same machine with one mistake for each check of the nested GRAFCETs, to see what the Problems panel reports</source>
        <translation>Dieselbe Maschine mit einem Fehler für jede Prüfung der eingebetteten GRAFCETs, um zu sehen, was das Fenster „Probleme“ meldet</translation>
    </message>
    <message>
        <source>The example %1 is missing from this build.</source>
        <translation>Das Beispiel %1 fehlt in diesem Build.</translation>
    </message>
    <message>
        <source>Bottle Filler (PackML)</source>
        <translation>Flaschenfüller (PackML)</translation>
    </message>
    <message>
        <source>A PackML unit with Production and Manual modes and a GRAFCET in Resetting, Starting, Execute, Stopping and Aborting</source>
        <translation>Eine PackML-Einheit mit den Betriebsarten Production und Manual und einem GRAFCET in Resetting, Starting, Execute, Stopping und Aborting</translation>
    </message>
</context>
<context>
    <name>FaultMenu</name>
    <message>
        <source>Fault not injected</source>
        <translation>Fehler nicht eingespeist</translation>
    </message>
    <message>
        <source>stuck at TRUE</source>
        <extracomment>a fault of a sensor of the virtual machine, shown beside its value</extracomment>
        <translation>klemmt auf TRUE</translation>
    </message>
    <message>
        <source>stuck at FALSE</source>
        <translation>klemmt auf FALSE</translation>
    </message>
    <message>
        <source>flickering</source>
        <translation>flackernd</translation>
    </message>
    <message>
        <source>stuck TRUE</source>
        <extracomment>a sensor&apos;s fault where space is short (the Machine tab); TRUE and FALSE stay as they are</extracomment>
        <translation>klemmt TRUE</translation>
    </message>
    <message>
        <source>stuck FALSE</source>
        <translation>klemmt FALSE</translation>
    </message>
    <message>
        <source>flicker</source>
        <translation>flackert</translation>
    </message>
    <message>
        <source>Fault of %1</source>
        <extracomment>%1: a sensor variable of the virtual machine
----------
%1: a cylinder or conveyor of the virtual machine</extracomment>
        <translation>Fehler von %1</translation>
    </message>
    <message>
        <source>Stuck at &amp;TRUE</source>
        <translation>Klemmt auf &amp;TRUE</translation>
    </message>
    <message>
        <source>Stuck at &amp;FALSE</source>
        <translation>Klemmt auf &amp;FALSE</translation>
    </message>
    <message>
        <source>F&amp;licker</source>
        <translation>F&amp;lackern</translation>
    </message>
    <message>
        <source>&amp;Clear Fault</source>
        <translation>Fehler &amp;beheben</translation>
    </message>
    <message>
        <source>Clear &amp;Jam</source>
        <translation>&amp;Blockade lösen</translation>
    </message>
    <message>
        <source>&amp;Jam</source>
        <translation>&amp;Blockieren</translation>
    </message>
</context>
<context>
    <name>GrafcetClipboard</name>
    <message>
        <source>The clipboard holds no GRAFCET steps</source>
        <translation>Die Zwischenablage enthält keine GRAFCET-Schritte</translation>
    </message>
    <message>
        <source>Nothing pasted: the GRAFCET steps on the clipboard are damaged (%1)</source>
        <extracomment>%1 what is wrong in the clipboard&apos;s data (in English), with where when known</extracomment>
        <translation>Nichts eingefügt: Die GRAFCET-Schritte in der Zwischenablage sind beschädigt (%1)</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <source>T%1 (%2 → %3): %4</source>
        <extracomment>a transition copied as text: %1 its number, %2 and %3 the steps it links, %4 its receptivity</extracomment>
        <translation>T%1 (%2 → %3): %4</translation>
    </message>
</context>
<context>
    <name>GrafcetExport</name>
    <message>
        <source>Nested GRAFCET drawn by GG Studio</source>
        <translation>Eingebetteter GRAFCET, gezeichnet mit GG Studio</translation>
    </message>
</context>
<context>
    <name>InitialStepRule</name>
    <message>
        <source>%1 is the initial step, which cannot be hidden; make another step initial first</source>
        <extracomment>%1 is a GEMMA step, e.g. A1</extracomment>
        <translation>%1 ist der Anfangsschritt, der nicht ausgeblendet werden kann; machen Sie zuerst einen anderen Schritt zum Anfangsschritt</translation>
    </message>
    <message>
        <source>%1 is hidden and cannot be the initial step; show it first</source>
        <extracomment>%1 is a GEMMA step, e.g. A3</extracomment>
        <translation>%1 ist ausgeblendet und kann nicht der Anfangsschritt sein; blenden Sie ihn zuerst ein</translation>
    </message>
</context>
<context>
    <name>MachineComponentItem</name>
    <message>
        <source>%1: %2</source>
        <extracomment>%1: a role of a machine component (&quot;extended&quot;); %2: the variable wired to it
----------
%1: a sensor variable (&quot;Clamped&quot;); %2: its fault (&quot;stuck FALSE&quot;)</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>(not wired)</source>
        <translation>(nicht verdrahtet)</translation>
    </message>
    <message>
        <source>%1, jammed</source>
        <extracomment>%1: the kind of a machine component (&quot;Double-acting cylinder&quot;), which a fault has stopped</extracomment>
        <translation>%1, blockiert</translation>
    </message>
</context>
<context>
    <name>MachineDiagnosticText</name>
    <message>
        <source>an input</source>
        <translation>ein Eingang</translation>
    </message>
    <message>
        <source>an output</source>
        <translation>ein Ausgang</translation>
    </message>
    <message>
        <source>an internal variable</source>
        <translation>eine interne Variable</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal names &apos;%3&apos;, which is no variable of the model.</source>
        <extracomment>%1: a machine component; %2: its role (extend, retracted...); %3: a name</extracomment>
        <translation>Das Signal %2 von %1 nennt &apos;%3&apos;, das keine Variable des Modells ist.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal is %3, %4; it needs %5.</source>
        <extracomment>%1: a machine component; %2: its role; %3: a variable; %4, %5: &quot;an input&quot;, &quot;an output&quot;...</extracomment>
        <translation>Das Signal %2 von %1 ist %3, %4; es braucht %5.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal is %3, of type %4; a machine signal is BOOL.</source>
        <extracomment>%4: an IEC type (INT)</extracomment>
        <translation>Das Signal %2 von %1 ist %3 vom Typ %4; ein Maschinensignal ist BOOL.</translation>
    </message>
    <message>
        <source>%3 is wired to %1&apos;s %2 signal and to %4&apos;s %5 signal: an input has one source.</source>
        <extracomment>%1, %4: machine components; %2, %5: their roles; %3: the input both are wired to</extracomment>
        <translation>%3 ist mit dem Signal %2 von %1 und dem Signal %5 von %4 verdrahtet: ein Eingang hat eine Quelle.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal %3 is driven by no action of the program: the component never moves.</source>
        <translation>Das Signal %2 (%3) von %1 wird von keiner Aktion des Programms angesteuert: die Komponente bewegt sich nie.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 is %3: out of range (travel times 1 to 3600000 ms, delays 0 to 3600000 ms, parts 0 to 1000000000).</source>
        <extracomment>%2: a parameter (extendMs, onDelayMs, parts); %3: its value</extracomment>
        <translation>%2 von %1 ist %3: außerhalb des Bereichs (Verfahrzeiten 1 bis 3600000 ms, Verzögerungen 0 bis 3600000 ms, Teile 0 bis 1000000000).</translation>
    </message>
    <message>
        <source>%1 has no variable for its %2 signal.</source>
        <translation>%1 hat keine Variable für sein Signal %2.</translation>
    </message>
    <message>
        <source>%1 feeds &apos;%2&apos;, which is no conveyor of the machine.</source>
        <translation>%1 beschickt &apos;%2&apos;, das kein Förderband der Maschine ist.</translation>
    </message>
</context>
<context>
    <name>MachineText</name>
    <message>
        <source>Double-acting cylinder</source>
        <translation>Doppeltwirkender Zylinder</translation>
    </message>
    <message>
        <source>Single-acting cylinder</source>
        <translation>Einfachwirkender Zylinder</translation>
    </message>
    <message>
        <source>Conveyor</source>
        <translation>Förderband</translation>
    </message>
    <message>
        <source>Lamp</source>
        <translation>Leuchte</translation>
    </message>
    <message>
        <source>Push button</source>
        <translation>Taster</translation>
    </message>
    <message>
        <source>Selector</source>
        <translation>Wahlschalter</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Not-Halt</translation>
    </message>
    <message>
        <source>Delayed sensor</source>
        <translation>Verzögerter Sensor</translation>
    </message>
    <message>
        <source>Part source</source>
        <translation>Teilequelle</translation>
    </message>
    <message>
        <source>extend</source>
        <translation>ausfahren</translation>
    </message>
    <message>
        <source>retract</source>
        <translation>einfahren</translation>
    </message>
    <message>
        <source>retracted</source>
        <translation>eingefahren</translation>
    </message>
    <message>
        <source>extended</source>
        <translation>ausgefahren</translation>
    </message>
    <message>
        <source>run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>part present</source>
        <translation>Teil vorhanden</translation>
    </message>
    <message>
        <source>lamp</source>
        <translation>Leuchte</translation>
    </message>
    <message>
        <source>input</source>
        <translation>Eingang</translation>
    </message>
    <message>
        <source>output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>sensor</source>
        <translation>Sensor</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>leer</translation>
    </message>
    <message>
        <source>Extend time (ms)</source>
        <translation>Ausfahrzeit (ms)</translation>
    </message>
    <message>
        <source>Retract time (ms)</source>
        <translation>Einfahrzeit (ms)</translation>
    </message>
    <message>
        <source>Travel time (ms)</source>
        <translation>Laufzeit (ms)</translation>
    </message>
    <message>
        <source>On delay (ms)</source>
        <translation>Einschaltverzögerung (ms)</translation>
    </message>
    <message>
        <source>Off delay (ms)</source>
        <translation>Ausschaltverzögerung (ms)</translation>
    </message>
    <message>
        <source>Parts</source>
        <translation>Teile</translation>
    </message>
    <message>
        <source>Normally closed</source>
        <translation>Öffner</translation>
    </message>
    <message>
        <source>Normally open</source>
        <translation>Schließer</translation>
    </message>
</context>
<context>
    <name>MoveGrafcetActionCommand</name>
    <message>
        <source>Move action %1 of %2 step %3 up</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Aktion %1 von Schritt %3 von %2 nach oben</translation>
    </message>
    <message>
        <source>Move action %1 of %2 step %3 down</source>
        <translation>Aktion %1 von Schritt %3 von %2 nach unten</translation>
    </message>
</context>
<context>
    <name>MovePropertyCommand</name>
    <message>
        <source>Move property %1</source>
        <translation>Eigenschaft %1 verschieben</translation>
    </message>
</context>
<context>
    <name>MoveVariableCommand</name>
    <message>
        <source>Move variable %1</source>
        <translation>Variable %1 verschieben</translation>
    </message>
</context>
<context>
    <name>NestedProblemText</name>
    <message>
        <source>the receptivity of T%2 of %1</source>
        <extracomment>%1: a GEMMA step; %2: the number of a transition of its nested GRAFCET</extracomment>
        <translation>der Weiterschaltbedingung von T%2 von %1</translation>
    </message>
    <message>
        <source>action %3 of step %2 of %1</source>
        <extracomment>%1: a GEMMA step; %2: a nested step&apos;s number; %3: the action&apos;s position in its list, from 1</extracomment>
        <translation>Aktion %3 von Schritt %2 von %1</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is not a declared variable.</source>
        <translation>In %1: &apos;%2&apos; ist keine deklarierte Variable.</translation>
    </message>
    <message>
        <source>In %1: a continuous action is N V or V IF &lt;condition&gt;.</source>
        <translation>In %1: eine kontinuierliche Aktion ist N V oder V IF &lt;Bedingung&gt;.</translation>
    </message>
    <message>
        <source>In %1: a stored action is S V, R V or V := &lt;expression&gt;.</source>
        <translation>In %1: eine gespeicherte Aktion ist S V, R V oder V := &lt;Ausdruck&gt;.</translation>
    </message>
    <message>
        <source>Syntax error in %1: %2.</source>
        <translation>Syntaxfehler in %1: %2.</translation>
    </message>
    <message>
        <source>Type error in %1: %2.</source>
        <translation>Typfehler in %1: %2.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is %3; this action needs a BOOL variable.</source>
        <extracomment>%3: an IEC type name (INT)</extracomment>
        <translation>In %1: &apos;%2&apos; ist %3; diese Aktion braucht eine BOOL-Variable.</translation>
    </message>
    <message>
        <source>In %1: %4 does not fit &apos;%2&apos; (%3): it cannot be assigned to it.</source>
        <extracomment>%2: the target variable; %3: its type; %4: the value as written</extracomment>
        <translation>In %1: %4 passt nicht zu &apos;%2&apos; (%3): es kann ihr nicht zugewiesen werden.</translation>
    </message>
    <message>
        <source>In %1: %2 names step %3, which the GRAFCET of %4 does not have.</source>
        <extracomment>%2: a step activity as written (X9); %3: its step number; %4: the GEMMA step</extracomment>
        <translation>In %1: %2 nennt Schritt %3, den der GRAFCET von %4 nicht hat.</translation>
    </message>
    <message>
        <source>In %1: %2 is longer than %3, the longest duration an IEC TIME (a TON preset) holds.</source>
        <extracomment>%2: a duration as written (25d/X1); %3: the longest IEC TIME</extracomment>
        <translation>In %1: %2 ist länger als %3, die längste Dauer, die ein IEC-TIME (die Vorgabe eines TON) fasst.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; divides by zero: on the PLC an integer division or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / 0)</extracomment>
        <translation>In %1: &apos;%2&apos; teilt durch null: auf der SPS hält eine ganzzahlige Division oder MOD durch null die Task mit einem Fehler an, eine REAL-Division ergibt INF oder NaN.</translation>
    </message>
    <message>
        <source>In %1: the divisor of &apos;%2&apos; can be zero: an integer division or MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / Batch)</extracomment>
        <translation>In %1: der Divisor von &apos;%2&apos; kann null sein: eine ganzzahlige Division oder MOD durch null hält die SPS mit einem Fehler an (und die Simulation), eine REAL-Division ergibt INF oder NaN.</translation>
    </message>
    <message>
        <source>In %1: %2 is an edge on a variable that is not BOOL.</source>
        <extracomment>%2: an edge as written (RE Level)</extracomment>
        <translation>In %1: %2 ist eine Flanke auf einer Variablen, die nicht BOOL ist.</translation>
    </message>
    <message>
        <source>In %1: %2 is for receptivities only: an action cannot read an edge or a step duration.</source>
        <translation>In %1: %2 gibt es nur in Weiterschaltbedingungen: eine Aktion kann keine Flanke und keine Schrittdauer lesen.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is an input: it is read from the machine, actions never write it.</source>
        <translation>In %1: &apos;%2&apos; ist ein Eingang: er wird von der Maschine gelesen, Aktionen schreiben ihn nie.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is %3; a continuous action needs a BOOL variable.</source>
        <extracomment>%3: an IEC type name (INT)</extracomment>
        <translation>In %1: &apos;%2&apos; ist %3; eine kontinuierliche Aktion braucht eine BOOL-Variable.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is also driven by continuous actions; a variable has either continuous or stored actions (the stored one is not generated).</source>
        <translation>In %1: &apos;%2&apos; wird auch von kontinuierlichen Aktionen angesteuert; eine Variable hat entweder kontinuierliche oder gespeicherte Aktionen (die gespeicherte wird nicht erzeugt).</translation>
    </message>
    <message>
        <source>In %1: invalid variable name: %2.</source>
        <translation>In %1: ungültiger Variablenname: %2.</translation>
    </message>
    <message>
        <source>In %1: the condition reads &apos;%2&apos;, a continuous output of the same GRAFCET.</source>
        <translation>In %1: die Bedingung liest &apos;%2&apos;, einen kontinuierlichen Ausgang desselben GRAFCET.</translation>
    </message>
    <message>
        <source>The receptivity of T%2 of %1 is empty: write TRUE for a transition that is always ready.</source>
        <translation>Die Weiterschaltbedingung von T%2 von %1 ist leer: schreiben Sie TRUE für eine Transition, die immer bereit ist.</translation>
    </message>
</context>
<context>
    <name>OperatorItem</name>
    <message>
        <source>switched on</source>
        <translation>eingeschaltet</translation>
    </message>
    <message>
        <source>switched off</source>
        <translation>ausgeschaltet</translation>
    </message>
    <message>
        <source>pressed</source>
        <translation>gedrückt</translation>
    </message>
    <message>
        <source>released</source>
        <translation>losgelassen</translation>
    </message>
</context>
<context>
    <name>PackMLDiagnosticText</name>
    <message>
        <source>The model has no unit mode.</source>
        <translation>Das Modell hat keine Betriebsart.</translation>
    </message>
    <message>
        <source>The initial mode %1 is not a unit mode of the model.</source>
        <translation>Die Anfangsbetriebsart %1 ist keine Betriebsart des Modells.</translation>
    </message>
    <message>
        <source>The initial state %1 is not Stopped, Idle or Aborted.</source>
        <translation>Der Anfangszustand %1 ist nicht Stopped, Idle oder Aborted.</translation>
    </message>
    <message>
        <source>The model&apos;s name &apos;%1&apos; cannot name the PROGRAM (it is no IEC identifier, or the generated code or a variable takes it): the PROGRAM is named %2.</source>
        <translation>Der Modellname „%1“ kann das PROGRAM nicht benennen (er ist kein IEC-Bezeichner, oder der erzeugte Code oder eine Variable verwendet ihn): das PROGRAM heißt %2.</translation>
    </message>
    <message>
        <source>Unit mode %1 is outside 1..31 (PackTags UnitMode).</source>
        <translation>Die Betriebsart %1 liegt außerhalb von 1..31 (PackTags UnitMode).</translation>
    </message>
    <message>
        <source>Unit mode %1 is given twice.</source>
        <translation>Die Betriebsart %1 ist doppelt angegeben.</translation>
    </message>
    <message>
        <source>Unit mode %1 is named %2, not &apos;%3&apos;.</source>
        <extracomment>%2: the fixed name of a base mode (Production, Maintenance, Manual)</extracomment>
        <translation>Die Betriebsart %1 heißt %2, nicht „%3“.</translation>
    </message>
    <message>
        <source>The name &apos;%2&apos; of unit mode %1 is not an IEC identifier, and it becomes part of the names of function blocks.</source>
        <translation>Der Name „%2“ der Betriebsart %1 ist kein IEC-Bezeichner, wird aber Teil der Namen von Funktionsbausteinen.</translation>
    </message>
    <message>
        <source>The name &apos;%2&apos; of unit mode %1 is one the generated code uses.</source>
        <translation>Der Name „%2“ der Betriebsart %1 wird vom erzeugten Code verwendet.</translation>
    </message>
    <message>
        <source>Unit mode %1 is named &apos;%2&apos;, as mode %3 is (ignoring case).</source>
        <translation>Die Betriebsart %1 heißt „%2“, wie die Betriebsart %3 (ohne Beachtung der Groß-/Kleinschreibung).</translation>
    </message>
    <message>
        <source>Mode %1 lists %2 as disabled, which every unit needs: ignored.</source>
        <translation>Die Betriebsart %1 führt %2 als deaktiviert, doch jede Einheit braucht diesen Zustand: ignoriert.</translation>
    </message>
    <message>
        <source>Mode %1 lists %2 as disabled, but it stays enabled while %3 is enabled.</source>
        <extracomment>%3: the enabled acting states of the loop (Holding, Unholding)</extracomment>
        <translation>Die Betriebsart %1 führt %2 als deaktiviert, doch der Zustand bleibt aktiviert, solange %3 aktiviert ist.</translation>
    </message>
    <message>
        <source>Mode %1 allows a mode change in %2, an acting state, half-way through its GRAFCET: ignored.</source>
        <translation>Die Betriebsart %1 erlaubt einen Betriebsartwechsel in %2, einem handelnden Zustand, mitten in seinem GRAFCET: ignoriert.</translation>
    </message>
    <message>
        <source>Mode %1 allows a mode change in %2, which it disables: no effect.</source>
        <translation>Die Betriebsart %1 erlaubt einen Betriebsartwechsel in %2, den sie deaktiviert: ohne Wirkung.</translation>
    </message>
    <message>
        <source>Mode %1 can never be current: it is not the initial mode, and no state allows a change into it from another mode.</source>
        <translation>Die Betriebsart %1 kann nie aktuell werden: sie ist nicht die Anfangsbetriebsart, und kein Zustand erlaubt den Wechsel aus einer anderen Betriebsart in sie.</translation>
    </message>
    <message>
        <source>In mode %1, no sequence of transitions leads to Execute from where the mode begins (counting a State Complete only where the state&apos;s GRAFCET writes Complete).</source>
        <translation>In der Betriebsart %1 führt keine Folge von Transitionen von ihrem Beginn nach Execute (ein State Complete zählt nur, wo das GRAFCET des Zustands Complete schreibt).</translation>
    </message>
    <message>
        <source>In mode %1, no sequence of transitions reaches %2 from where the mode begins: it is never active.</source>
        <translation>In der Betriebsart %1 erreicht keine Folge von Transitionen von ihrem Beginn aus %2: der Zustand ist nie aktiv.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: Aborting never writes Complete: nothing leaves Aborting, so the unit can never reach Aborted.</source>
        <translation>Das GRAFCET von %1: Aborting schreibt nie Complete: nichts verlässt Aborting, die Einheit kann Aborted also nie erreichen.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: %2 never writes Complete: only Stop or Abort leave the state.</source>
        <translation>Das GRAFCET von %1: %2 schreibt nie Complete: nur Stop oder Abort verlassen den Zustand.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: %2 is kept, but the mode disables the state: it generates no code.</source>
        <translation>Das GRAFCET von %1: %2 bleibt erhalten, aber die Betriebsart deaktiviert den Zustand: es erzeugt keinen Code.</translation>
    </message>
    <message>
        <source>there is no mode %1</source>
        <translation>es gibt keine Betriebsart %1</translation>
    </message>
    <message>
        <source>that is the mode itself</source>
        <translation>das ist die Betriebsart selbst</translation>
    </message>
    <message>
        <source>mode %1 has no GRAFCET of its own there</source>
        <translation>die Betriebsart %1 hat dort kein eigenes GRAFCET</translation>
    </message>
    <message>
        <source>%1: %2 runs the same GRAFCET as mode %3, but %4.</source>
        <extracomment>%4: why (there is no mode 9, that is the mode itself, ...)</extracomment>
        <translation>%1: %2 führt dasselbe GRAFCET aus wie die Betriebsart %3, aber %4.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: Execute writes Complete, which nothing reads in the 2022 edition: use the Complete command.</source>
        <translation>Das GRAFCET von %1: Execute schreibt Complete, was in der Ausgabe 2022 nichts liest: verwenden Sie den Befehl Complete.</translation>
    </message>
    <message>
        <source>The condition of %1 is empty: write FALSE for a command that comes only through CntrlCmd.</source>
        <translation>Die Bedingung von %1 ist leer: schreiben Sie FALSE für einen Befehl, der nur über CntrlCmd kommt.</translation>
    </message>
    <message>
        <source>Command %2 has the same condition as command %1: one rising edge issues both, and only the first in priority acts.</source>
        <translation>Der Befehl %2 hat dieselbe Bedingung wie der Befehl %1: eine steigende Flanke gibt beide aus, und nur der erste in der Priorität wirkt.</translation>
    </message>
    <message>
        <source>The request of mode %2 has the same condition as the request of mode %1: one rising edge issues both, and only the first in priority acts.</source>
        <translation>Die Anforderung der Betriebsart %2 hat dieselbe Bedingung wie die Anforderung der Betriebsart %1: eine steigende Flanke gibt beide aus, und nur die erste in der Priorität wirkt.</translation>
    </message>
    <message>
        <source>The condition of %1 reads the output &apos;%2&apos;: commands and mode requests come from an operator, a line controller or an alarm, so read an input or an internal variable.</source>
        <translation>Die Bedingung von %1 liest den Ausgang „%2“: Befehle und Betriebsartanforderungen kommen von einem Bediener, einer Liniensteuerung oder einem Alarm, lesen Sie also einen Eingang oder eine interne Variable.</translation>
    </message>
    <message>
        <source>No enabled state of any mode accepts the command %1: it generates no code.</source>
        <translation>Kein aktivierter Zustand einer Betriebsart nimmt den Befehl %1 an: er erzeugt keinen Code.</translation>
    </message>
    <message>
        <source>The Complete command exists in the 2022 edition only: its setting is ignored in this 2015 model.</source>
        <translation>Den Befehl Complete gibt es nur in der Ausgabe 2022: seine Einstellung wird in diesem Modell der Ausgabe 2015 ignoriert.</translation>
    </message>
    <message>
        <source>The option completeInSuspendedHeld is for the 2022 edition only: it is ignored in this 2015 model.</source>
        <translation>Die Option completeInSuspendedHeld gilt nur für die Ausgabe 2022: sie wird in diesem Modell der Ausgabe 2015 ignoriert.</translation>
    </message>
    <message>
        <source>a step activity</source>
        <translation>eine Schrittaktivität</translation>
    </message>
    <message>
        <source>a step duration</source>
        <translation>eine Schrittdauer</translation>
    </message>
    <message>
        <source>an edge</source>
        <translation>eine Flanke</translation>
    </message>
    <message>
        <source>The condition of %1 uses %2 (&apos;%3&apos;), which only the texts of nested GRAFCETs have; a command or request is already the rising edge of its condition.</source>
        <extracomment>%2: what the condition uses (a step activity, an edge...); %3: the text as written</extracomment>
        <translation>Die Bedingung von %1 verwendet %2 („%3“), was nur die Texte verschachtelter GRAFCETs haben; ein Befehl oder eine Anforderung ist bereits die steigende Flanke seiner Bedingung.</translation>
    </message>
    <message>
        <source>mode %1</source>
        <extracomment>A unit mode of a PackML model: &quot;mode Manual&quot;</extracomment>
        <translation>Betriebsart %1</translation>
    </message>
    <message>
        <source>command %1</source>
        <extracomment>A PackML command: &quot;command Hold&quot;</extracomment>
        <translation>Befehl %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>A state in a unit mode: &quot;Manual: Execute&quot;</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>request of mode %1</source>
        <extracomment>The request condition of a unit mode</extracomment>
        <translation>Anforderung der Betriebsart %1</translation>
    </message>
    <message>
        <source>The variable name &apos;%1&apos; is one the generated PackML code uses (PackTags, the state machine, the function blocks or the program %2).</source>
        <translation>Der Variablenname „%1“ wird vom erzeugten PackML-Code verwendet (PackTags, der Zustandsautomat, die Funktionsbausteine oder das Programm %2).</translation>
    </message>
</context>
<context>
    <name>PackmlChartExport</name>
    <message>
        <source>PackML chart drawn by GG Studio</source>
        <translation>PackML-Diagramm, gezeichnet von GG Studio</translation>
    </message>
    <message>
        <source>Unit mode %1</source>
        <translation>Betriebsart %1</translation>
    </message>
</context>
<context>
    <name>PackmlSimulationText</name>
    <message>
        <source>%1 cannot be entered in %2: %3</source>
        <extracomment>%1: a unit mode (Manual), %2: a PackML state (Execute), %3: why</extracomment>
        <translation>%1 kann in %2 nicht aktiviert werden: %3</translation>
    </message>
    <message>
        <source>%1; %2 grants it in no state</source>
        <extracomment>%1: a refusal, %2: the current unit mode</extracomment>
        <translation>%1; %2 gewährt ihn in keinem Zustand</translation>
    </message>
    <message>
        <source>%1; it can be entered in %2</source>
        <extracomment>%1: a refusal, %2: PackML states (&quot;Stopped, Idle, Aborted&quot;)</extracomment>
        <translation>%1; er kann in %2 aktiviert werden</translation>
    </message>
    <message>
        <source>%1 allows no mode change there</source>
        <translation>%1 erlaubt dort keinen Betriebsartwechsel</translation>
    </message>
    <message>
        <source>%1 disables this state</source>
        <translation>%1 deaktiviert diesen Zustand</translation>
    </message>
    <message>
        <source>%1 is not granted: %2, lower-numbered, is granted in the same scan</source>
        <extracomment>%2: the unit mode granted instead</extracomment>
        <translation>%1 wird nicht gewährt: %2 mit kleinerer Nummer wird im selben Zyklus gewährt</translation>
    </message>
    <message>
        <source>%1 is requested: it is already the current mode</source>
        <translation>%1 wird angefordert: das ist bereits die aktuelle Betriebsart</translation>
    </message>
    <message>
        <source>%1 names no unit mode</source>
        <translation>%1 bezeichnet keine Betriebsart der Einheit</translation>
    </message>
    <message>
        <source>the SC of %1</source>
        <translation>das SC von %1</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2</source>
        <extracomment>%1: a PackML command (Hold), %2: a state (Idle)</extracomment>
        <translation>%1 wird in %2 nicht angenommen</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2 in %3: the mode disables where it leads</source>
        <extracomment>%1: a command, %2: a state, %3: a unit mode</extracomment>
        <translation>%1 wird in %2 in %3 nicht angenommen: die Betriebsart deaktiviert den Zielzustand</translation>
    </message>
    <message>
        <source>%1 is pre-empted by %2</source>
        <extracomment>%2: the transition that fired instead (&quot;Execute-Stop-&gt;Stopped&quot;)</extracomment>
        <translation>%1 wird von %2 verdrängt</translation>
    </message>
    <message>
        <source>%1 names no command</source>
        <translation>%1 bezeichnet keinen Befehl</translation>
    </message>
    <message>
        <source>the receptivity of T%1 of %2</source>
        <extracomment>%1: a transition number of a nested GRAFCET, %2: its function block instance</extracomment>
        <translation>die Transitionsbedingung von T%1 von %2</translation>
    </message>
    <message>
        <source>action %1 of step %2 of %3</source>
        <extracomment>%1: an action&apos;s position, %2: a step number, %3: a function block instance</extracomment>
        <translation>Aktion %1 von Schritt %2 von %3</translation>
    </message>
    <message>
        <source>the condition of the %1 command</source>
        <extracomment>%1: a PackML command (Start)</extracomment>
        <translation>die Bedingung des Befehls %1</translation>
    </message>
    <message>
        <source>the request condition of mode %1</source>
        <extracomment>%1: a unit mode (Manual)</extracomment>
        <translation>die Anforderungsbedingung der Betriebsart %1</translation>
    </message>
    <message>
        <source>cannot set %1: %2</source>
        <extracomment>%1: a variable or instance, %2: why (from the simulator)</extracomment>
        <translation>%1 kann nicht gesetzt werden: %2</translation>
    </message>
    <message>
        <source>expected state %1, the state is %2</source>
        <translation>Zustand %1 erwartet, der Zustand ist %2</translation>
    </message>
    <message>
        <source>expected mode %1, the mode is %2</source>
        <translation>Betriebsart %1 erwartet, die Betriebsart ist %2</translation>
    </message>
    <message>
        <source>expected %1 = %2, it is %3</source>
        <translation>%1 = %2 erwartet, der Wert ist %3</translation>
    </message>
    <message>
        <source>expected %1 to fire, no transition fired</source>
        <translation>Schalten von %1 erwartet, keine Transition hat geschaltet</translation>
    </message>
    <message>
        <source>expected %1 to fire, %2 fired</source>
        <translation>Schalten von %1 erwartet, %2 hat geschaltet</translation>
    </message>
    <message>
        <source>expected no transition to fire, %1 fired</source>
        <translation>kein Schalten erwartet, %1 hat geschaltet</translation>
    </message>
    <message>
        <source>scan %1: %2</source>
        <extracomment>%1: a scan number, %2: what did not hold</extracomment>
        <translation>Zyklus %1: %2</translation>
    </message>
    <message>
        <source>Stopped at scan %1: integer division by zero in %2 (%3 in &apos;%4&apos;). On the PLC the task stops with a fault; Reset to run again.</source>
        <extracomment>%1: a scan number, %2: where (a condition, a receptivity, an action), %3: the division as written, %4: the text</extracomment>
        <translation>Angehalten in Zyklus %1: ganzzahlige Division durch null in %2 (%3 in „%4“). In der SPS stoppt die Task mit einem Fehler; zum erneuten Start zurücksetzen.</translation>
    </message>
    <message>
        <source>%1: granted</source>
        <extracomment>a unit mode request that the mode manager granted</extracomment>
        <translation>%1: gewährt</translation>
    </message>
    <message>
        <source>%1: not granted</source>
        <translation>%1: nicht gewährt</translation>
    </message>
    <message>
        <source>%1: fired %2</source>
        <extracomment>%1: a command, %2: the transition it fired (&quot;Idle-Start-&gt;Execute&quot;)</extracomment>
        <translation>%1: %2 hat geschaltet</translation>
    </message>
    <message>
        <source>%1: no transition fired</source>
        <translation>%1: keine Transition hat geschaltet</translation>
    </message>
</context>
<context>
    <name>PackmlTexts</name>
    <message>
        <source>Wait state</source>
        <translation>Wartezustand</translation>
    </message>
    <message>
        <source>Acting state</source>
        <translation>Aktiver Zustand</translation>
    </message>
    <message>
        <source>Dual state: acts and waits for a command</source>
        <translation>Dualer Zustand: handelt und wartet auf einen Befehl</translation>
    </message>
    <message>
        <source>Clears the faults that led to Aborted, then goes to Stopped.</source>
        <translation>Behebt die Fehler, die zu Aborted führten, und geht dann nach Stopped.</translation>
    </message>
    <message>
        <source>Powered and stationary; waits for Reset.</source>
        <translation>Eingeschaltet und in Ruhe; wartet auf Reset.</translation>
    </message>
    <message>
        <source>Prepares the unit to produce, then goes to Execute.</source>
        <translation>Bereitet die Einheit auf die Produktion vor und geht dann nach Execute.</translation>
    </message>
    <message>
        <source>Reset and ready; waits for Start.</source>
        <translation>Zurückgesetzt und bereit; wartet auf Start.</translation>
    </message>
    <message>
        <source>Paused by a condition outside the unit (starved, blocked); waits for Unsuspend.</source>
        <translation>Angehalten durch eine Bedingung außerhalb der Einheit (Mangel, Rückstau); wartet auf Unsuspend.</translation>
    </message>
    <message>
        <source>Produces; waits for Hold, Suspend or the end of the batch.</source>
        <translation>Produziert; wartet auf Hold, Suspend oder das Ende der Charge.</translation>
    </message>
    <message>
        <source>Brings the unit to a controlled stop, then goes to Stopped.</source>
        <translation>Bringt die Einheit zu einem kontrollierten Halt und geht dann nach Stopped.</translation>
    </message>
    <message>
        <source>Brings the unit to a quick safe stop, then goes to Aborted.</source>
        <translation>Bringt die Einheit schnell und sicher zum Stillstand und geht dann nach Aborted.</translation>
    </message>
    <message>
        <source>Stopped after an abort; waits for Clear.</source>
        <translation>Nach einem Abbruch gestoppt; wartet auf Clear.</translation>
    </message>
    <message>
        <source>Brings production to a controlled pause for an internal reason, then goes to Held.</source>
        <translation>Hält die Produktion aus einem internen Grund kontrolliert an und geht dann nach Held.</translation>
    </message>
    <message>
        <source>Paused for an internal reason; waits for Unhold.</source>
        <translation>Aus einem internen Grund angehalten; wartet auf Unhold.</translation>
    </message>
    <message>
        <source>Prepares to resume production after Held, then goes to Execute.</source>
        <translation>Bereitet die Wiederaufnahme der Produktion nach Held vor und geht dann nach Execute.</translation>
    </message>
    <message>
        <source>Brings production to a controlled pause for an outside reason, then goes to Suspended.</source>
        <translation>Hält die Produktion aus einem äußeren Grund kontrolliert an und geht dann nach Suspended.</translation>
    </message>
    <message>
        <source>Prepares to resume production after Suspended, then goes to Execute.</source>
        <translation>Bereitet die Wiederaufnahme der Produktion nach Suspended vor und geht dann nach Execute.</translation>
    </message>
    <message>
        <source>Brings the unit to its ready state, then goes to Idle.</source>
        <translation>Bringt die Einheit in ihren Bereitzustand und geht dann nach Idle.</translation>
    </message>
    <message>
        <source>Ends the batch in order, then goes to Complete.</source>
        <translation>Beendet die Charge geordnet und geht dann nach Complete.</translation>
    </message>
    <message>
        <source>The batch is complete; waits for Reset.</source>
        <translation>Die Charge ist abgeschlossen; wartet auf Reset.</translation>
    </message>
    <message>
        <source>Reset: make the unit ready to start again.</source>
        <translation>Reset: die Einheit wieder startbereit machen.</translation>
    </message>
    <message>
        <source>Start: begin producing.</source>
        <translation>Start: mit der Produktion beginnen.</translation>
    </message>
    <message>
        <source>Stop: bring the unit to a controlled stop.</source>
        <translation>Stop: die Einheit kontrolliert anhalten.</translation>
    </message>
    <message>
        <source>Hold: pause production for an internal reason.</source>
        <translation>Hold: die Produktion aus einem internen Grund anhalten.</translation>
    </message>
    <message>
        <source>Unhold: resume production after a Hold.</source>
        <translation>Unhold: die Produktion nach einem Hold fortsetzen.</translation>
    </message>
    <message>
        <source>Suspend: pause production for an outside reason.</source>
        <translation>Suspend: die Produktion aus einem äußeren Grund anhalten.</translation>
    </message>
    <message>
        <source>Unsuspend: resume production after a Suspend.</source>
        <translation>Unsuspend: die Produktion nach einem Suspend fortsetzen.</translation>
    </message>
    <message>
        <source>Abort: stop the unit at once, safely.</source>
        <translation>Abort: die Einheit sofort und sicher stillsetzen.</translation>
    </message>
    <message>
        <source>Clear: clear the faults after an Abort.</source>
        <translation>Clear: die Fehler nach einem Abort beheben.</translation>
    </message>
    <message>
        <source>Complete: end the batch.</source>
        <translation>Complete: die Charge beenden.</translation>
    </message>
</context>
<context>
    <name>PackmlVerificationText</name>
    <message>
        <source>In %1, Execute, entered again from the Hold or Suspend loop, started afresh instead of resuming where it was paused.</source>
        <translation>In %1 hat Execute, aus der Hold- oder Suspend-Schleife wieder betreten, neu begonnen, statt dort fortzufahren, wo es unterbrochen wurde.</translation>
    </message>
    <message>
        <source>In %1, Execute resumed where it should have started afresh from its initial situation.</source>
        <translation>In %1 hat Execute fortgesetzt, wo es in seiner Anfangssituation neu hätte beginnen müssen.</translation>
    </message>
    <message>
        <source>In %1, Execute resumed in a situation other than the one it was paused in.</source>
        <translation>In %1 hat Execute in einer anderen Situation fortgesetzt als der, in der es unterbrochen wurde.</translation>
    </message>
    <message>
        <source>The verification was not exhaustive (its time or size limit, timers or numeric inputs it explores only in part): stuck states, states never active and commands never accepted were not decided, and the absence of other findings is not a proof.</source>
        <translation>Die Verifikation war nicht erschöpfend (ihr Zeit- oder Größenlimit, Timer oder numerische Eingänge, die sie nur teilweise untersucht): Festsitzende Zustände, nie aktive Zustände und nie angenommene Befehle wurden nicht entschieden, und das Fehlen weiterer Befunde ist kein Beweis.</translation>
    </message>
    <message>
        <source>In %1, the GRAFCET of %2 can reach a situation from which Complete never becomes TRUE: only Stop or Abort then leave %2.</source>
        <translation>In %1 kann das GRAFCET von %2 eine Situation erreichen, aus der Complete nie TRUE wird: Dann verlassen nur Stop oder Abort %2.</translation>
    </message>
    <message>
        <source>In %1, Aborting can reach a situation from which Aborted is never reached: nothing leaves it.</source>
        <translation>In %1 kann Aborting eine Situation erreichen, aus der Aborted nie erreicht wird: Nichts verlässt sie.</translation>
    </message>
    <message>
        <source>%2 was active at the end of a scan in %1, a mode that disables it.</source>
        <translation>%2 war am Ende eines Zyklus in %1 aktiv, einer Betriebsart, die es deaktiviert.</translation>
    </message>
    <message>
        <source>The mode changed from %1 in %2, a state where this change is not allowed.</source>
        <translation>Die Betriebsart wechselte von %1 in %2, einem Zustand, in dem dieser Wechsel nicht erlaubt ist.</translation>
    </message>
    <message>
        <source>%1 is never the current mode.</source>
        <translation>%1 ist nie die aktuelle Betriebsart.</translation>
    </message>
    <message>
        <source>%2 is enabled in %1 but never active there.</source>
        <translation>%2 ist in %1 aktiviert, dort aber nie aktiv.</translation>
    </message>
    <message>
        <source>The %1 command is accepted in no reachable configuration.</source>
        <translation>Der Befehl %1 wird in keiner erreichbaren Konfiguration angenommen.</translation>
    </message>
    <message>
        <source>In %1, continuous outputs are TRUE at the end of the scan that enters %2: %3.</source>
        <translation>In %1 sind kontinuierliche Ausgänge am Ende des Zyklus TRUE, der %2 betritt: %3.</translation>
    </message>
    <message>
        <source>In %1, stored outputs can still be TRUE when %2 is entered: %3.</source>
        <translation>In %1 können gespeicherte Ausgänge beim Betreten von %2 noch TRUE sein: %3.</translation>
    </message>
    <message>
        <source>Stuck states were not decided in %1: timers longer than one cycle may or may not have elapsed, and the ways to Complete found there let timers elapse in an order the PLC&apos;s may not. Every other finding is decided.</source>
        <translation>Blockierte Zustände wurden in %1 nicht entschieden: Timer, die länger als ein Zyklus sind, können abgelaufen sein oder nicht, und die dort gefundenen Wege zu Complete lassen Timer in einer Reihenfolge ablaufen, die die der SPS möglicherweise nicht einhalten. Alle anderen Befunde sind entschieden.</translation>
    </message>
</context>
<context>
    <name>PartSourceItem</name>
    <message>
        <source>Unlimited parts</source>
        <translation>Unbegrenzte Teile</translation>
    </message>
    <message>
        <source>Parts left: %1</source>
        <translation>Verbleibende Teile: %1</translation>
    </message>
    <message>
        <source>feeds no conveyor</source>
        <translation>speist kein Förderband</translation>
    </message>
    <message>
        <source>feeds %1</source>
        <translation>speist %1</translation>
    </message>
</context>
<context>
    <name>PasteVariablesCommand</name>
    <message>
        <source>Paste variable %1</source>
        <translation>Variable %1 einfügen</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n variables</source>
        <translation>
            <numerusform>%n Variable einfügen</numerusform>
            <numerusform>%n Variablen einfügen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PictureFile</name>
    <message>
        <source>The SVG picture could not be drawn.</source>
        <translation>Das SVG-Bild konnte nicht gezeichnet werden.</translation>
    </message>
    <message>
        <source>Not enough memory for a picture of %1 × %2 pixels.</source>
        <translation>Nicht genug Speicher für ein Bild mit %1 × %2 Pixeln.</translation>
    </message>
    <message>
        <source>The PNG picture could not be encoded.</source>
        <translation>Das PNG-Bild konnte nicht kodiert werden.</translation>
    </message>
    <message>
        <source>The PDF document could not be drawn.</source>
        <translation>Das PDF-Dokument konnte nicht gezeichnet werden.</translation>
    </message>
</context>
<context>
    <name>PropertyProblemText</name>
    <message>
        <source>&apos;%1&apos; is not a declared variable</source>
        <translation>&apos;%1&apos; ist keine deklarierte Variable</translation>
    </message>
    <message>
        <source>there is no visible GEMMA step &apos;%1&apos;</source>
        <translation>es gibt keinen sichtbaren GEMMA-Schritt &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the step %1 has no nested GRAFCET</source>
        <translation>der Schritt %1 hat keinen eingebetteten GRAFCET</translation>
    </message>
    <message>
        <source>the GRAFCET of %1 has no step %2</source>
        <translation>der GRAFCET von %1 hat keinen Schritt %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is only defined when verifying with single faults (Simulation &gt; Verify with Single Faults, with the machine)</source>
        <translation>&apos;%1&apos; ist nur beim Verifizieren mit einzelnen Fehlern definiert (Simulation &gt; Mit einzelnen Fehlern verifizieren, mit der Maschine)</translation>
    </message>
</context>
<context>
    <name>RecoveryPrompt</name>
    <message>
        <source>an untitled model</source>
        <translation>ein unbenanntes Modell</translation>
    </message>
    <message>
        <source>Discard Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen verwerfen</translation>
    </message>
    <message>
        <source>Delete the autosaved copy of %1 for good?</source>
        <translation>Die automatisch gesicherte Kopie von %1 endgültig löschen?</translation>
    </message>
    <message>
        <source>The changes it holds cannot be recovered afterwards.</source>
        <translation>Die darin enthaltenen Änderungen können danach nicht mehr wiederhergestellt werden.</translation>
    </message>
    <message>
        <source>Delete Copy</source>
        <translation>Kopie löschen</translation>
    </message>
    <message>
        <source>&amp;Keep Copy</source>
        <translation>Kopie &amp;behalten</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>GG Studio ended without saving %1.</source>
        <translation>GG Studio wurde beendet, ohne %1 zu speichern.</translation>
    </message>
    <message>
        <source>Autosave kept a copy on %1. Recover it? You can then save it or discard it.</source>
        <translation>Die automatische Sicherung hat am %1 eine Kopie angelegt. Wiederherstellen? Sie können sie danach speichern oder verwerfen.</translation>
    </message>
    <message>
        <source>The original file can no longer be identified (moved, deleted or changed since, or named by an older version): saving the recovered model will ask for a file.</source>
        <translation>Die ursprüngliche Datei lässt sich nicht mehr bestimmen (verschoben, gelöscht oder seitdem geändert, oder von einer älteren Version benannt): Beim Speichern des wiederhergestellten Modells wird nach einer Datei gefragt.</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>Discard…</source>
        <translation>Verwerfen…</translation>
    </message>
    <message>
        <source>&amp;Not Now</source>
        <translation>&amp;Nicht jetzt</translation>
    </message>
    <message>
        <source>The autosaved copy could not be read.</source>
        <translation>Die automatisch gesicherte Kopie konnte nicht gelesen werden.</translation>
    </message>
</context>
<context>
    <name>RemoveGrafcetActionCommand</name>
    <message>
        <source>Remove action %1 of %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Aktion %1 von Schritt %3 von %2 entfernen</translation>
    </message>
</context>
<context>
    <name>RemoveMachineComponentCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>%1 entfernen</translation>
    </message>
</context>
<context>
    <name>RemoveModeCommand</name>
    <message>
        <source>Remove mode %1</source>
        <translation>Betriebsart %1 entfernen</translation>
    </message>
</context>
<context>
    <name>RemovePropertyCommand</name>
    <message>
        <source>Remove property %1</source>
        <translation>Eigenschaft %1 entfernen</translation>
    </message>
</context>
<context>
    <name>RemoveVariableCommand</name>
    <message>
        <source>Remove variable %1</source>
        <translation>Variable %1 entfernen</translation>
    </message>
</context>
<context>
    <name>RenameModeCommand</name>
    <message>
        <source>Rename mode %1</source>
        <translation>Betriebsart %1 umbenennen</translation>
    </message>
</context>
<context>
    <name>RenameVariableCommand</name>
    <message>
        <source>Rename variable %1 to %2</source>
        <translation>Variable %1 in %2 umbenennen</translation>
    </message>
    <message>
        <source>a variable named &apos;%1&apos; already exists (IEC names ignore case)</source>
        <translation>eine Variable namens „%1“ ist bereits vorhanden (IEC-Namen unterscheiden keine Groß- und Kleinschreibung)</translation>
    </message>
</context>
<context>
    <name>RenumberGrafcetStepCommand</name>
    <message>
        <source>Renumber %1 step %2 to %3</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET, %3 its new number</extracomment>
        <translation>Schritt %2 von %1 in %3 umnummerieren</translation>
    </message>
</context>
<context>
    <name>ResetModelCommand</name>
    <message>
        <source>Reset to template</source>
        <translation>Auf Vorlage zurücksetzen</translation>
    </message>
</context>
<context>
    <name>SetCommandCommentCommand</name>
    <message>
        <source>Edit comment of command %1</source>
        <translation>Kommentar des Befehls %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetCommandConditionCommand</name>
    <message>
        <source>Edit condition of command %1</source>
        <translation>Bedingung des Befehls %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetConditionCommand</name>
    <message>
        <source>Edit condition of %1</source>
        <translation>Bedingung von %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetCycleTimeCommand</name>
    <message>
        <source>Set cycle time to %1 ms</source>
        <translation>Zykluszeit auf %1 ms setzen</translation>
    </message>
</context>
<context>
    <name>SetDialectCommand</name>
    <message>
        <source>CODESYS</source>
        <translation>CODESYS</translation>
    </message>
    <message>
        <source>IEC</source>
        <translation>IEC</translation>
    </message>
    <message>
        <source>Set dialect to %1</source>
        <translation>Dialekt auf %1 setzen</translation>
    </message>
</context>
<context>
    <name>SetElementsHiddenCommand</name>
    <message numerus="yes">
        <source>Hide %n element(s)</source>
        <translation>
            <numerusform>%n Element ausblenden</numerusform>
            <numerusform>%n Elemente ausblenden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show %n element(s)</source>
        <translation>
            <numerusform>%n Element einblenden</numerusform>
            <numerusform>%n Elemente einblenden</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SetEvolutionRuleCommand</name>
    <message>
        <source>Set evolution rule to until stable</source>
        <translation>Entwicklungsregel auf „bis stabil“ setzen</translation>
    </message>
    <message>
        <source>Set evolution rule to one evolution per scan</source>
        <translation>Entwicklungsregel auf „eine Entwicklung pro Zyklus“ setzen</translation>
    </message>
</context>
<context>
    <name>SetGrafcetActionCommand</name>
    <message>
        <source>Set action %1 of %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Aktion %1 von Schritt %3 von %2 ändern</translation>
    </message>
</context>
<context>
    <name>SetGrafcetChoiceCommand</name>
    <message>
        <source>Give %1 its own GRAFCET in mode %2</source>
        <translation>%1 in Betriebsart %2 einen eigenen GRAFCET geben</translation>
    </message>
    <message>
        <source>Run in %1 of mode %2 the GRAFCET of mode %3</source>
        <translation>In %1 der Betriebsart %2 den GRAFCET der Betriebsart %3 ausführen</translation>
    </message>
    <message>
        <source>Remove the GRAFCET of %1 in mode %2</source>
        <translation>GRAFCET von %1 in Betriebsart %2 entfernen</translation>
    </message>
</context>
<context>
    <name>SetGrafcetStepCommentCommand</name>
    <message>
        <source>Edit comment of %1 step %2</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET: &quot;Edit comment of F1 step 3&quot;</extracomment>
        <translation>Kommentar von Schritt %2 von %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetGrafcetStepInitialCommand</name>
    <message>
        <source>Make %1 step %2 initial</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET</extracomment>
        <translation>Schritt %2 von %1 zum Anfangsschritt machen</translation>
    </message>
    <message>
        <source>Make %1 step %2 not initial</source>
        <translation>Schritt %2 von %1 nicht mehr Anfangsschritt</translation>
    </message>
</context>
<context>
    <name>SetInitialStepCommand</name>
    <message>
        <source>Make %1 the initial step</source>
        <translation>%1 zum Anfangsschritt machen</translation>
    </message>
</context>
<context>
    <name>SetModeCommentCommand</name>
    <message>
        <source>Edit comment of mode %1</source>
        <translation>Kommentar der Betriebsart %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetModeRequestCommand</name>
    <message>
        <source>Edit request condition of mode %1</source>
        <translation>Anforderungsbedingung der Betriebsart %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetModeStatesCommand</name>
    <message>
        <source>Change disabled states of mode %1</source>
        <translation>Deaktivierte Zustände der Betriebsart %1 ändern</translation>
    </message>
    <message>
        <source>Change mode-change states of mode %1</source>
        <translation>Zustände für den Betriebsartwechsel der Betriebsart %1 ändern</translation>
    </message>
</context>
<context>
    <name>SetModelNameCommand</name>
    <message>
        <source>Rename model</source>
        <translation>Modell umbenennen</translation>
    </message>
</context>
<context>
    <name>SetNegatedCommand</name>
    <message>
        <source>Negate %1</source>
        <translation>%1 negieren</translation>
    </message>
    <message>
        <source>Remove negation of %1</source>
        <translation>Negation von %1 aufheben</translation>
    </message>
</context>
<context>
    <name>SetPackmlInitialModeCommand</name>
    <message>
        <source>Set initial mode to %1</source>
        <translation>Anfangsbetriebsart auf %1 setzen</translation>
    </message>
</context>
<context>
    <name>SetPackmlInitialStateCommand</name>
    <message>
        <source>Set initial state to %1</source>
        <translation>Anfangszustand auf %1 setzen</translation>
    </message>
</context>
<context>
    <name>SetPackmlOptionsCommand</name>
    <message>
        <source>Change PackML edition and options</source>
        <translation>PackML-Ausgabe und -Optionen ändern</translation>
    </message>
</context>
<context>
    <name>SetPriorityCommand</name>
    <message>
        <source>Set priority of %1 to %2</source>
        <translation>Priorität von %1 auf %2 setzen</translation>
    </message>
</context>
<context>
    <name>SetPropertyCommentCommand</name>
    <message>
        <source>Edit comment of property %1</source>
        <translation>Kommentar von Eigenschaft %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetPropertyTextCommand</name>
    <message>
        <source>Edit property %1</source>
        <translation>Eigenschaft %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetReceptivityCommand</name>
    <message>
        <source>Set receptivity of %1 T%2</source>
        <extracomment>%1 is the GEMMA step, %2 the transition number of its nested GRAFCET: &quot;Set receptivity of F1 T3&quot;</extracomment>
        <translation>Weiterschaltbedingung von %1 T%2 ändern</translation>
    </message>
</context>
<context>
    <name>SetStepCommentCommand</name>
    <message>
        <source>Edit comment of %1</source>
        <translation>Kommentar von %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetStepHiddenCommand</name>
    <message>
        <source>Hide step %1</source>
        <translation>Schritt %1 ausblenden</translation>
    </message>
    <message>
        <source>Show step %1</source>
        <translation>Schritt %1 einblenden</translation>
    </message>
</context>
<context>
    <name>SetStepTypeCommand</name>
    <message>
        <source>macro-step</source>
        <translation>Makroschritt</translation>
    </message>
    <message>
        <source>enclosing step</source>
        <translation>einschließender Schritt</translation>
    </message>
    <message>
        <source>simple step</source>
        <translation>einfacher Schritt</translation>
    </message>
    <message>
        <source>Set %1 to %2</source>
        <translation>Typ von %1 festlegen: %2</translation>
    </message>
</context>
<context>
    <name>SetTokensCommand</name>
    <message>
        <source>Set tokens of %1</source>
        <translation>Merker von %1 festlegen</translation>
    </message>
</context>
<context>
    <name>SetTransitionHiddenCommand</name>
    <message>
        <source>Hide transition %1</source>
        <translation>Transition %1 ausblenden</translation>
    </message>
    <message>
        <source>Show transition %1</source>
        <translation>Transition %1 einblenden</translation>
    </message>
</context>
<context>
    <name>SetVariableCommentCommand</name>
    <message>
        <source>Edit comment of %1</source>
        <translation>Kommentar von %1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>SetVariableDefaultCommand</name>
    <message>
        <source>Set default of %1</source>
        <translation>Anfangswert von %1 festlegen</translation>
    </message>
</context>
<context>
    <name>SetVariableKindCommand</name>
    <message>
        <source>Set kind of %1 to output</source>
        <translation>Art von %1 auf Ausgang setzen</translation>
    </message>
    <message>
        <source>Set kind of %1 to internal</source>
        <translation>Art von %1 auf intern setzen</translation>
    </message>
    <message>
        <source>Set kind of %1 to input</source>
        <translation>Art von %1 auf Eingang setzen</translation>
    </message>
</context>
<context>
    <name>SetVariableTypeCommand</name>
    <message>
        <source>Set type of %1 to %2</source>
        <translation>Typ von %1 auf %2 setzen</translation>
    </message>
</context>
<context>
    <name>SimulationText</name>
    <message>
        <source>%1 = %2 (token of %3)</source>
        <extracomment>a token variable, its value, then the literal it stores (&quot;NOT Stop&quot;)</extracomment>
        <translation>%1 = %2 (Merker von %3)</translation>
    </message>
    <message>
        <source>%1 is %2</source>
        <extracomment>an IEC expression of a condition, then TRUE or FALSE</extracomment>
        <translation>%1 ist %2</translation>
    </message>
    <message>
        <source>%1 is %2 (%3)</source>
        <extracomment>an IEC expression of a condition, TRUE or FALSE, then the values it reads (&quot;Speed = 3&quot;)</extracomment>
        <translation>%1 ist %2 (%3)</translation>
    </message>
    <message>
        <source>The condition cannot be used: it is FALSE.</source>
        <translation>Die Bedingung ist nicht verwendbar: Sie ist FALSE.</translation>
    </message>
    <message>
        <source>cannot apply: %1</source>
        <extracomment>%1: why, from the simulator (English)</extracomment>
        <translation>nicht anwendbar: %1</translation>
    </message>
    <message>
        <source>expected step %1, active step is %2</source>
        <translation>Schritt %1 erwartet, aktiver Schritt ist %2</translation>
    </message>
    <message>
        <source>expected step %1, no visible step is active (State = %2)</source>
        <translation>Schritt %1 erwartet, kein sichtbarer Schritt ist aktiv (State = %2)</translation>
    </message>
    <message>
        <source>expected %1 to fire, no transition fired</source>
        <translation>%1 sollte schalten, keine Transition hat geschaltet</translation>
    </message>
    <message>
        <source>expected %1 to fire, %2 fired</source>
        <translation>%1 sollte schalten, %2 hat geschaltet</translation>
    </message>
    <message>
        <source>expected no transition to fire, %1 fired</source>
        <translation>keine Transition sollte schalten, %1 hat geschaltet</translation>
    </message>
    <message>
        <source>expected token %1 = %2, it is %3</source>
        <translation>Merker %1 = %2 erwartet, er ist %3</translation>
    </message>
    <message>
        <source>expected %1 = %2, it is %3</source>
        <extracomment>a variable, the value expected, the value it has</extracomment>
        <translation>%1 = %2 erwartet, der Wert ist %3</translation>
    </message>
    <message>
        <source>unknown variable &apos;%1&apos;</source>
        <translation>unbekannte Variable &apos;%1&apos;</translation>
    </message>
    <message>
        <source>expected Entry = %1, it is %2</source>
        <translation>Entry = %1 erwartet, ist %2</translation>
    </message>
    <message>
        <source>expected %1.Complete = %2, it is %3</source>
        <translation>%1.Complete = %2 erwartet, ist %3</translation>
    </message>
    <message>
        <source>%1.Complete = FALSE</source>
        <extracomment>a macro-step or enclosing step; the transition waits for its Complete</extracomment>
        <translation>%1.Complete = FALSE</translation>
    </message>
    <message>
        <source>%1 fires first</source>
        <extracomment>a transition of higher priority whose condition holds</extracomment>
        <translation>%1 schaltet zuerst</translation>
    </message>
    <message>
        <source>scan %1: %2</source>
        <extracomment>a scan number, then what differed</extracomment>
        <translation>Zyklus %1: %2</translation>
    </message>
    <message>
        <source>expected &apos;at SCAN:&apos; at the start of the line, found %1</source>
        <extracomment>%1: the word found in quotes, or &quot;the end of the line&quot;; &apos;at SCAN:&apos; is scenario syntax</extracomment>
        <translation>&apos;at SCAN:&apos; am Zeilenanfang erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected a scan number after &apos;at&apos;, found %1</source>
        <translation>Zyklusnummer nach &apos;at&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected &apos;:&apos; after the scan number, found %1</source>
        <translation>&apos;:&apos; nach der Zyklusnummer erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected &apos;set&apos; or &apos;expect&apos;, found %1</source>
        <translation>&apos;set&apos; oder &apos;expect&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected a variable name or &apos;complete STEP&apos;, found %1</source>
        <translation>Variablenname oder &apos;complete STEP&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected a step id after &apos;complete&apos;, found %1</source>
        <translation>Schrittkennung nach &apos;complete&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected a step id after &apos;step&apos;, found %1</source>
        <translation>Schrittkennung nach &apos;step&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected a transition id or &apos;none&apos; after &apos;fired&apos;, found %1</source>
        <translation>Transitionskennung oder &apos;none&apos; nach &apos;fired&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected a token name after &apos;token&apos;, found %1</source>
        <translation>Merkername nach &apos;token&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected a variable name after &apos;variable&apos;, found %1</source>
        <translation>Variablenname nach &apos;variable&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the step id, found %1</source>
        <translation>&apos;=&apos; nach der Schrittkennung erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the variable name, found %1</source>
        <translation>&apos;=&apos; nach dem Variablennamen erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the token name, found %1</source>
        <translation>&apos;=&apos; nach dem Merkernamen erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after &apos;entry&apos;, found %1</source>
        <translation>&apos;=&apos; nach &apos;entry&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected a value after &apos;=&apos;, found %1</source>
        <translation>Wert nach &apos;=&apos; erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected TRUE or FALSE, found %1</source>
        <translation>TRUE oder FALSE erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected TRUE, FALSE or auto, found %1</source>
        <extracomment>auto is scenario syntax</extracomment>
        <translation>TRUE, FALSE oder auto erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected &apos;,&apos; or the end of the line, found %1</source>
        <translation>&apos;,&apos; oder Zeilenende erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>expected the end of the line, found %1</source>
        <translation>Zeilenende erwartet, %1 gefunden</translation>
    </message>
    <message>
        <source>scans are numbered from 1</source>
        <translation>Zyklen werden ab 1 gezählt</translation>
    </message>
    <message>
        <source>%1 is %2: %3</source>
        <extracomment>a variable, its IEC type (INT), then why the value does not fit it</extracomment>
        <translation>%1 ist vom Typ %2: %3</translation>
    </message>
    <message>
        <source>step %1 is hidden: it does not exist for the simulator</source>
        <translation>Schritt %1 ist ausgeblendet: Für den Simulator existiert er nicht</translation>
    </message>
    <message>
        <source>unknown step &apos;%1&apos;</source>
        <translation>unbekannter Schritt &apos;%1&apos;</translation>
    </message>
    <message>
        <source>step %1 is a simple step: it has no Complete</source>
        <translation>Schritt %1 ist ein einfacher Schritt: Er hat kein Complete</translation>
    </message>
    <message>
        <source>transition %1 is not effective (it or one of its steps is hidden)</source>
        <translation>Transition %1 ist nicht wirksam (sie oder einer ihrer Schritte ist ausgeblendet)</translation>
    </message>
    <message>
        <source>unknown transition &apos;%1&apos;</source>
        <translation>unbekannte Transition &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown token &apos;%1&apos;</source>
        <translation>unbekannter Merker &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the end of the line</source>
        <translation>das Zeilenende</translation>
    </message>
    <message>
        <source>invalid UTF-8: a scenario file must be UTF-8 text</source>
        <translation>ungültiges UTF-8: eine Szenariodatei muss UTF-8-Text sein</translation>
    </message>
    <message>
        <source>%1&apos;s Complete is set to two values in scan %2: %3 on line %4, %5 on line %6</source>
        <extracomment>a step id, a scan number, then each value with the line that sets it</extracomment>
        <translation>Complete von %1 erhält in Zyklus %2 zwei Werte: %3 in Zeile %4, %5 in Zeile %6</translation>
    </message>
    <message>
        <source>%1 is set to two values in scan %2: %3 on line %4, %5 on line %6</source>
        <extracomment>a variable, a scan number, then each value with the line that sets it</extracomment>
        <translation>%1 erhält in Zyklus %2 zwei Werte: %3 in Zeile %4, %5 in Zeile %6</translation>
    </message>
    <message>
        <source>expected the active steps of %1 to be %2, they are %3</source>
        <extracomment>%1: a GEMMA step; %2, %3: lists of nested step numbers</extracomment>
        <translation>erwartet waren die aktiven Schritte %2 in %1, sie sind %3</translation>
    </message>
    <message>
        <source>expected %1.Unstable = %2, it is %3</source>
        <translation>erwartet war %1.Unstable = %2, es ist %3</translation>
    </message>
    <message>
        <source>expected step, fired, token, variable, entry, complete or nested after &apos;expect&apos;, found %1</source>
        <extracomment>step, fired, token, variable, entry and complete are scenario syntax</extracomment>
        <translation>step, fired, token, variable, entry, complete oder nested nach „expect“ erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;nested&apos;, found %1</source>
        <translation>nach „nested“ wird eine Schritt-ID erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected &apos;steps&apos; or &apos;unstable&apos; after the step id, found %1</source>
        <extracomment>steps and unstable are scenario syntax</extracomment>
        <translation>nach der Schritt-ID wird „steps“ oder „unstable“ erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected a step number, found %1</source>
        <translation>eine Schrittnummer wird erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>%1 is an output variable: the program writes it, a scenario sets only inputs</source>
        <translation>%1 ist eine Ausgangsvariable: das Programm schreibt sie, ein Szenario setzt nur Eingänge</translation>
    </message>
    <message>
        <source>%1 is an internal variable: the program writes it, a scenario sets only inputs</source>
        <translation>%1 ist eine interne Variable: das Programm schreibt sie, ein Szenario setzt nur Eingänge</translation>
    </message>
    <message>
        <source>step %1 has no nested GRAFCET</source>
        <translation>Schritt %1 hat keinen eingebetteten GRAFCET</translation>
    </message>
    <message>
        <source>the Complete of %1 comes from its nested GRAFCET: it cannot be set</source>
        <translation>das Complete von %1 kommt aus seinem eingebetteten GRAFCET: es kann nicht gesetzt werden</translation>
    </message>
    <message>
        <source>step %1 is not active</source>
        <extracomment>an upstream step of a nested GRAFCET&apos;s transition</extracomment>
        <translation>Schritt %1 ist nicht aktiv</translation>
    </message>
    <message>
        <source>steps %1 are not active</source>
        <extracomment>the upstream steps of a nested GRAFCET&apos;s transition (&quot;2, 3&quot;)</extracomment>
        <translation>Schritte %1 sind nicht aktiv</translation>
    </message>
    <message>
        <source>no rising edge of %1 this scan (%1 = %2, at the end of the previous scan %3)</source>
        <extracomment>%1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan</extracomment>
        <translation>keine steigende Flanke von %1 in diesem Zyklus (%1 = %2, am Ende des vorigen Zyklus %3)</translation>
    </message>
    <message>
        <source>no falling edge of %1 this scan (%1 = %2, at the end of the previous scan %3)</source>
        <extracomment>%1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan</extracomment>
        <translation>keine fallende Flanke von %1 in diesem Zyklus (%1 = %2, am Ende des vorigen Zyklus %3)</translation>
    </message>
    <message>
        <source>%1 is FALSE: step %2 active for %3 ms of %4 ms</source>
        <extracomment>%1: a time-dependent receptivity (&quot;5s/X2&quot;); %2: its step; %3 of %4: elapsed and set time in ms</extracomment>
        <translation>%1 ist FALSE: Schritt %2 seit %3 ms von %4 ms aktiv</translation>
    </message>
    <message>
        <source>%1 is not the active step: its GRAFCET does not evolve in the next scan</source>
        <extracomment>a macro-step or enclosing step</extracomment>
        <translation>%1 ist nicht der aktive Schritt: sein GRAFCET entwickelt sich im nächsten Zyklus nicht</translation>
    </message>
    <message>
        <source>scan number %1 is too large: a scenario runs at most %2 scans</source>
        <extracomment>%2: the highest scan number a scenario may name</extracomment>
        <translation>die Zyklusnummer %1 ist zu groß: ein Szenario läuft höchstens %2 Zyklen</translation>
    </message>
    <message>
        <source>expected a command name after &apos;command&apos;, found %1</source>
        <extracomment>&apos;command&apos; is scenario syntax</extracomment>
        <translation>nach &apos;command&apos; wird ein Befehlsname erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected a mode name or number after &apos;mode&apos;, found %1</source>
        <extracomment>&apos;mode&apos; is scenario syntax</extracomment>
        <translation>nach &apos;mode&apos; wird ein Betriebsartname oder eine Betriebsartnummer erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected a state name after &apos;state&apos;, found %1</source>
        <extracomment>&apos;state&apos; is scenario syntax</extracomment>
        <translation>nach &apos;state&apos; wird ein Zustandsname erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;</source>
        <translation>unbekannter Befehl &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown unit mode &apos;%1&apos;</source>
        <translation>unbekannte Betriebsart &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown state &apos;%1&apos;</source>
        <translation>unbekannter Zustand &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown instance &apos;%1&apos;</source>
        <extracomment>%1: a PackML function block instance (Production_Resetting)</extracomment>
        <translation>unbekannte Instanz &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is for PackML models only</source>
        <extracomment>%1: scenario syntax (&quot;command&quot;, &quot;expect state&quot;)</extracomment>
        <translation>&apos;%1&apos; gilt nur für PackML-Modelle</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is for GEMMA models only</source>
        <extracomment>%1: scenario syntax (&quot;expect step&quot;, &quot;set complete&quot;)</extracomment>
        <translation>&apos;%1&apos; gilt nur für GEMMA-Modelle</translation>
    </message>
    <message>
        <source>a %1 in scan %2 right after the one of line %3 is not seen: the request must be FALSE for one scan in between</source>
        <extracomment>%1: &quot;command&quot; or &quot;mode&quot; (scenario syntax); %2: a scan number; %3: a line number</extracomment>
        <translation>ein %1 in Zyklus %2 direkt nach dem aus Zeile %3 wird nicht erkannt: die Anforderung muss dazwischen einen Zyklus lang FALSE sein</translation>
    </message>
    <message>
        <source>%1 is a sensor of the machine&apos;s %2: the machine sets it; set it by hand in open loop only</source>
        <extracomment>%1: a variable; %2: the name of a component of the virtual machine (&quot;Clamp&quot;)</extracomment>
        <translation>%1 ist ein Sensor der Maschinenkomponente %2: die Maschine setzt ihn; setzen Sie ihn nur im offenen Regelkreis von Hand</translation>
    </message>
    <message>
        <source>expected a sensor or component name after &apos;fault&apos;, found %1</source>
        <extracomment>&apos;fault&apos; is scenario syntax</extracomment>
        <translation>Sensor- oder Komponentenname nach &apos;fault&apos; erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>expected stuck, flicker, jam or clear after the name, found %1</source>
        <extracomment>stuck, flicker, jam and clear are scenario syntax</extracomment>
        <translation>stuck, flicker, jam oder clear nach dem Namen erwartet, gefunden: %1</translation>
    </message>
    <message>
        <source>a fault needs the virtual machine: run the scenario in closed loop, on a model with a machine</source>
        <translation>ein Fehler braucht die virtuelle Maschine: spielen Sie das Szenario im geschlossenen Regelkreis ab, an einem Modell mit Maschine</translation>
    </message>
    <message>
        <source>%1 is an operator input of the machine&apos;s %2: the user drives it with set; a fault applies to the machine&apos;s sensors</source>
        <extracomment>%1: a variable; %2: the name of a component of the virtual machine (&quot;Start&quot;); &apos;set&apos; is scenario syntax</extracomment>
        <translation>%1 ist ein Bedienereingang von %2 der Maschine: der Benutzer steuert ihn mit set; ein Fehler betrifft die Sensoren der Maschine</translation>
    </message>
    <message>
        <source>%1 is no sensor of the machine: a fault applies to the inputs a component writes</source>
        <translation>%1 ist kein Sensor der Maschine: ein Fehler betrifft die Eingänge, die eine Komponente schreibt</translation>
    </message>
    <message>
        <source>no component &apos;%1&apos; in the machine</source>
        <translation>keine Komponente &apos;%1&apos; in der Maschine</translation>
    </message>
    <message>
        <source>%1 is a %2: only cylinders and conveyors jam</source>
        <extracomment>%1: a component of the virtual machine; %2: its kind as the file spells it (&quot;lamp&quot;, &quot;push-button&quot;)</extracomment>
        <translation>%1 ist vom Typ %2: nur Zylinder und Förderbänder blockieren</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is neither a sensor nor a component of the machine</source>
        <translation>&apos;%1&apos; ist weder ein Sensor noch eine Komponente der Maschine</translation>
    </message>
</context>
<context>
    <name>SpecificationExport</name>
    <message>
        <source>%1 specification</source>
        <extracomment>the specification&apos;s title and the file name it is saved under; %1 is the model&apos;s name</extracomment>
        <translation>%1 Spezifikation</translation>
    </message>
    <message>
        <source>GEMMA chart</source>
        <translation>GEMMA-Diagramm</translation>
    </message>
    <message>
        <source>States</source>
        <translation>Zustände</translation>
    </message>
    <message>
        <source>Transitions</source>
        <translation>Transitionen</translation>
    </message>
    <message>
        <source>Variables</source>
        <translation>Variablen</translation>
    </message>
    <message>
        <source>Nested GRAFCETs</source>
        <translation>Eingebettete GRAFCETs</translation>
    </message>
    <message>
        <source>Generated code</source>
        <translation>Erzeugter Code</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Spezifikation</translation>
    </message>
    <message>
        <source>GEMMA-GRAFCET specification</source>
        <translation>GEMMA-GRAFCET-Spezifikation</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n Fehler</numerusform>
            <numerusform>%n Fehler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>noch nicht gespeichert</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <source>Initial state</source>
        <translation>Anfangszustand</translation>
    </message>
    <message>
        <source>PLC task cycle</source>
        <translation>Zyklus der SPS-Task</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Code dialect</source>
        <translation>Code-Dialekt</translation>
    </message>
    <message>
        <source>Nested GRAFCET evolution</source>
        <translation>Entwicklung der eingebetteten GRAFCETs</translation>
    </message>
    <message>
        <source>Until stable, in one call of its function block</source>
        <translation>Bis stabil, in einem Aufruf seines Funktionsbausteins</translation>
    </message>
    <message>
        <source>One evolution per PLC scan</source>
        <translation>Eine Entwicklung pro SPS-Zyklus</translation>
    </message>
    <message>
        <source>Checks</source>
        <translation>Prüfungen</translation>
    </message>
    <message>
        <source>No problems found</source>
        <translation>Keine Probleme gefunden</translation>
    </message>
    <message>
        <source>Written by</source>
        <translation>Erstellt mit</translation>
    </message>
    <message>
        <source>GG Studio %1</source>
        <translation>GG Studio %1</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>Inhalt</translation>
    </message>
    <message>
        <source>GEMMA chart, continued</source>
        <translation>GEMMA-Diagramm, Fortsetzung</translation>
    </message>
    <message>
        <source>States, transitions and variables</source>
        <translation>Zustände, Transitionen und Variablen</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>GRAFCET</source>
        <translation>GRAFCET</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Kommentar</translation>
    </message>
    <message>
        <source>%1, initial</source>
        <translation>%1, Anfangsschritt</translation>
    </message>
    <message numerus="yes">
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n Schritt</numerusform>
            <numerusform>%n Schritte</numerusform>
        </translation>
    </message>
    <message>
        <source>The visible states of the GEMMA chart, in state order. A macro-step or an enclosing step runs its nested GRAFCET while it is active.</source>
        <translation>Die sichtbaren Zustände des GEMMA-Diagramms in der Reihenfolge der Zustände. Ein Makroschritt oder ein einschließender Schritt führt seinen eingebetteten GRAFCET aus, solange er aktiv ist.</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transition</translation>
    </message>
    <message>
        <source>Priority</source>
        <translation>Priorität</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Bedingung</translation>
    </message>
    <message>
        <source>Tokens</source>
        <translation>Merker</translation>
    </message>
    <message>
        <source>%1, negated</source>
        <translation>%1, negiert</translation>
    </message>
    <message>
        <source>The transitions that take part: visible, between visible states. A state evaluates its transitions by priority, 1 first; a negated transition fires when its condition is FALSE.</source>
        <translation>Die wirksamen Transitionen: sichtbar, zwischen sichtbaren Zuständen. Ein Zustand wertet seine Transitionen nach Priorität aus, 1 zuerst; eine negierte Transition schaltet, wenn ihre Bedingung FALSE ist.</translation>
    </message>
    <message>
        <source>No transition takes part.</source>
        <translation>Keine Transition ist wirksam.</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Anfangswert</translation>
    </message>
    <message>
        <source>The declared variables, in declaration order. Inputs are read from the machine, outputs written by the actions of the nested GRAFCETs, internal variables are the program&apos;s memory. A variable without a default starts at its type&apos;s (FALSE, 0).</source>
        <translation>Die deklarierten Variablen in der Reihenfolge ihrer Deklaration. Eingänge werden von der Maschine gelesen, Ausgänge von den Aktionen der eingebetteten GRAFCETs geschrieben, interne Variablen sind der Speicher des Programms. Eine Variable ohne Anfangswert beginnt mit dem ihres Typs (FALSE, 0).</translation>
    </message>
    <message>
        <source>No variables are declared.</source>
        <translation>Es sind keine Variablen deklariert.</translation>
    </message>
    <message numerus="yes">
        <source>%n transition(s)</source>
        <translation>
            <numerusform>%n Transition</numerusform>
            <numerusform>%n Transitionen</numerusform>
        </translation>
    </message>
    <message>
        <source>function block %1</source>
        <translation>Funktionsbaustein %1</translation>
    </message>
    <message>
        <source>This GRAFCET has no steps yet.</source>
        <translation>Dieser GRAFCET hat noch keine Schritte.</translation>
    </message>
    <message>
        <source>Nested GRAFCET of %1, continued</source>
        <translation>Eingebetteter GRAFCET von %1, Fortsetzung</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Steps of %1</source>
        <translation>Schritte von %1</translation>
    </message>
    <message>
        <source>GG Studio generates the PLC program as IEC 61131-3 Structured Text by the Hierarchical Design Pattern: the program %1 holds the active GEMMA state and evaluates its transitions by priority, and each visible macro-step or enclosing step is a function block that %1 calls while that state is active. This outline gives the program organisation units and their interfaces; File &gt; Export Structured Text and Export PLCopen XML write the code itself.</source>
        <translation>GG Studio erzeugt das SPS-Programm als Structured Text nach IEC 61131-3 nach dem Hierarchical Design Pattern: Das Programm %1 hält den aktiven GEMMA-Zustand und wertet dessen Transitionen nach Priorität aus, und jeder sichtbare Makroschritt oder einschließende Schritt ist ein Funktionsbaustein, den %1 aufruft, solange dieser Zustand aktiv ist. Diese Übersicht nennt die Programmorganisationseinheiten und ihre Schnittstellen; Datei &gt; Strukturierten Text (ST) exportieren und PLCopen XML exportieren schreiben den Code selbst.</translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s): the generated code marks each one with a comment.</source>
        <translation>
            <numerusform>Das Modell hat %n Fehler: Der erzeugte Code markiert ihn mit einem Kommentar.</numerusform>
            <numerusform>Das Modell hat %n Fehler: Der erzeugte Code markiert jeden mit einem Kommentar.</numerusform>
        </translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Konfiguration</translation>
    </message>
    <message>
        <source>Resource</source>
        <translation>Ressource</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Task</translation>
    </message>
    <message>
        <source>%1: cyclic, every %2, priority %3</source>
        <translation>%1: zyklisch, alle %2, Priorität %3</translation>
    </message>
    <message>
        <source>Program instance</source>
        <translation>Programminstanz</translation>
    </message>
    <message>
        <source>Global variable list</source>
        <translation>Globale Variablenliste</translation>
    </message>
    <message>
        <source>The GEMMA layer: it holds the active state in State, evaluates that state&apos;s transitions by priority and calls the function block of a state with nested behaviour while that state is active.</source>
        <translation>Die GEMMA-Ebene: Sie hält den aktiven Zustand in State, wertet die Transitionen dieses Zustands nach Priorität aus und ruft den Funktionsbaustein eines Zustands mit eingebettetem Verhalten auf, solange dieser Zustand aktiv ist.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 (page %2). %3 calls it through its instance %4 while %4 is active.</source>
        <translation>Der eingebettete GRAFCET von %1 (Seite %2). %3 ruft ihn über seine Instanz %4 auf, solange %4 aktiv ist.</translation>
    </message>
    <message>
        <source>The nested behaviour of %1, not written yet: until it is, the function block completes at once. %2 calls it through its instance %3.</source>
        <translation>Das eingebettete Verhalten von %1, noch nicht geschrieben: Bis dahin meldet der Funktionsbaustein sofort Complete. %2 ruft ihn über seine Instanz %3 auf.</translation>
    </message>
    <message>
        <source>Declaration</source>
        <translation>Deklaration</translation>
    </message>
    <message>
        <source>Initial value</source>
        <translation>Anfangswert</translation>
    </message>
    <message>
        <source>Global variables it reads (VAR_EXTERNAL): %1.</source>
        <translation>Globale Variablen, die er liest (VAR_EXTERNAL): %1.</translation>
    </message>
    <message>
        <source>Its own variables (VAR): %1.</source>
        <translation>Eigene Variablen (VAR): %1.</translation>
    </message>
    <message>
        <source>Global variables</source>
        <translation>Globale Variablen</translation>
    </message>
    <message>
        <source>in the VAR_GLOBAL of the configuration %1</source>
        <translation>im VAR_GLOBAL der Konfiguration %1</translation>
    </message>
    <message>
        <source>in the global variable list %1</source>
        <translation>in der globalen Variablenliste %1</translation>
    </message>
    <message>
        <source>The declared variables (page %1) are the program&apos;s global variables, %2.</source>
        <translation>Die deklarierten Variablen (Seite %1) sind die globalen Variablen des Programms, %2.</translation>
    </message>
    <message>
        <source>The generator adds these:</source>
        <translation>Der Generator fügt diese hinzu:</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
    <message>
        <source>PackML chart</source>
        <translation>PackML-Diagramm</translation>
    </message>
    <message>
        <source>Commands, modes and variables</source>
        <translation>Befehle, Betriebsarten und Variablen</translation>
    </message>
    <message>
        <source>Unit mode %1</source>
        <translation>Betriebsart %1</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Befehle</translation>
    </message>
    <message>
        <source>Unit modes</source>
        <translation>Betriebsarten</translation>
    </message>
    <message>
        <source>PackML, 2022 edition</source>
        <translation>PackML, Ausgabe 2022</translation>
    </message>
    <message>
        <source>PackML, 2015 edition</source>
        <translation>PackML, Ausgabe 2015</translation>
    </message>
    <message>
        <source>Hold accepted in Suspended</source>
        <translation>Hold in Suspended angenommen</translation>
    </message>
    <message>
        <source>Complete accepted in Suspended and Held</source>
        <translation>Complete in Suspended und Held angenommen</translation>
    </message>
    <message>
        <source>%1; options: %2</source>
        <translation>%1; Optionen: %2</translation>
    </message>
    <message>
        <source>Template</source>
        <translation>Vorlage</translation>
    </message>
    <message>
        <source>Initial unit mode</source>
        <translation>Anfangsbetriebsart</translation>
    </message>
    <message>
        <source>PackML specification</source>
        <translation>PackML-Spezifikation</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Befehl</translation>
    </message>
    <message>
        <source>CntrlCmd</source>
        <translation>CntrlCmd</translation>
    </message>
    <message>
        <source>The commands of the edition, with the condition whose rising edge issues each one (besides CntrlCmd). A command a state does not accept is ignored there.</source>
        <translation>Die Befehle der Ausgabe mit der Bedingung, deren steigende Flanke jeden auslöst (neben CntrlCmd). Ein Befehl, den ein Zustand nicht annimmt, wird dort ignoriert.</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Betriebsart</translation>
    </message>
    <message>
        <source>Request condition</source>
        <translation>Anforderungsbedingung</translation>
    </message>
    <message>
        <source>Disabled states</source>
        <translation>Deaktivierte Zustände</translation>
    </message>
    <message>
        <source>Mode change allowed in</source>
        <translation>Betriebsartwechsel erlaubt in</translation>
    </message>
    <message>
        <source>The unit modes, in number order. A mode skips its disabled states; the unit changes to a mode when its request condition rises while the current mode allows a change in the current state.</source>
        <translation>Die Betriebsarten in Nummernfolge. Eine Betriebsart überspringt ihre deaktivierten Zustände; die Einheit wechselt in eine Betriebsart, wenn deren Anforderungsbedingung steigt, während die aktuelle Betriebsart im aktuellen Zustand einen Wechsel erlaubt.</translation>
    </message>
    <message>
        <source>Nested GRAFCET</source>
        <translation>Untergeordneter GRAFCET</translation>
    </message>
    <message>
        <source>Nested GRAFCETs in %1</source>
        <translation>Untergeordnete GRAFCETs in %1</translation>
    </message>
    <message>
        <source>None: the mode disables this state</source>
        <translation>Keiner: die Betriebsart deaktiviert diesen Zustand</translation>
    </message>
    <message>
        <source>Own: %1</source>
        <translation>Eigener: %1</translation>
    </message>
    <message>
        <source>Same as mode %1: %2</source>
        <translation>Wie Betriebsart %1: %2</translation>
    </message>
    <message>
        <source>Same as mode %1, which does not exist</source>
        <translation>Wie Betriebsart %1, die es nicht gibt</translation>
    </message>
    <message>
        <source>None: the state completes at once</source>
        <translation>Keiner: der Zustand ist sofort abgeschlossen</translation>
    </message>
    <message>
        <source>None: Execute waits for a command</source>
        <translation>Keiner: Execute wartet auf einen Befehl</translation>
    </message>
    <message>
        <source>Nested GRAFCET %1, continued</source>
        <translation>Untergeordneter GRAFCET %1, Fortsetzung</translation>
    </message>
    <message>
        <source>GG Studio generates the PLC program as IEC 61131-3 Structured Text by the PackML design pattern: the program %1 is the state and mode manager, with the PackTags interface; it calls, in each acting state and Execute, the function block instance of the current unit mode and state, whose State Complete ends that state. This outline gives the program organisation units and their interfaces; File &gt; Export Structured Text and Export PLCopen XML write the code itself.</source>
        <translation>GG Studio erzeugt das SPS-Programm als IEC-61131-3-Strukturierten Text nach dem PackML-Entwurfsmuster: das Programm %1 ist die Zustands- und Betriebsartverwaltung mit der PackTags-Schnittstelle; es ruft in jedem handelnden Zustand und in Execute die Funktionsbausteininstanz der aktuellen Betriebsart und des aktuellen Zustands auf, deren State Complete diesen Zustand beendet. Diese Übersicht nennt die Programmorganisationseinheiten und ihre Schnittstellen; Datei &gt; Strukturierten Text exportieren und PLCopen XML exportieren schreiben den Code selbst.</translation>
    </message>
    <message>
        <source>The PackML state and mode manager: it latches the commands and mode requests, holds the current state and unit mode in StateCurrent and UnitModeCurrent, evaluates the current state&apos;s transitions in the current mode and calls the function block instance of that mode and state.</source>
        <translation>Die PackML-Zustands- und Betriebsartverwaltung: sie speichert die Befehle und Betriebsartanforderungen, hält den aktuellen Zustand und die aktuelle Betriebsart in StateCurrent und UnitModeCurrent, wertet die Transitionen des aktuellen Zustands in der aktuellen Betriebsart aus und ruft die Funktionsbausteininstanz dieser Betriebsart und dieses Zustands auf.</translation>
    </message>
    <message>
        <source>The nested GRAFCET %1 (page %2). %3 calls it while the unit is in %4 in a mode that runs it; its Complete is that state&apos;s State Complete.</source>
        <translation>Der untergeordnete GRAFCET %1 (Seite %2). %3 ruft ihn auf, solange die Einheit in %4 ist, in einer Betriebsart, die ihn ausführt; sein Complete ist das State Complete dieses Zustands.</translation>
    </message>
    <message>
        <source>The function block of %1 in the modes without a GRAFCET there: %2</source>
        <translation>Der Funktionsbaustein von %1 in den Betriebsarten ohne GRAFCET dort: %2</translation>
    </message>
    <message>
        <source>it completes at once.</source>
        <translation>er ist sofort abgeschlossen.</translation>
    </message>
    <message>
        <source>it does nothing, Execute waits for a command.</source>
        <translation>er tut nichts, Execute wartet auf einen Befehl.</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>Component</source>
        <translation>Komponente</translation>
    </message>
    <message>
        <source>Wiring</source>
        <translation>Verdrahtung</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>unbegrenzt</translation>
    </message>
    <message>
        <source>Feeds %1</source>
        <translation>Speist %1</translation>
    </message>
    <message>
        <source>The virtual machine the simulation runs the program against, in closed loop: after each scan the components move one cycle time from the outputs wired to them and set the sensors the next scan reads; operator inputs stay the user&apos;s. Times are in milliseconds, counted in whole cycles.</source>
        <translation>Die virtuelle Maschine, gegen die die Simulation das Programm im geschlossenen Regelkreis ausführt: Nach jedem Zyklus bewegen sich die Komponenten um eine Zykluszeit gemäß den mit ihnen verdrahteten Ausgängen und setzen die Sensoren, die der nächste Zyklus liest; Bedienereingänge bleiben beim Benutzer. Zeiten in Millisekunden, in ganzen Zyklen gezählt.</translation>
    </message>
    <message>
        <source>The machine at rest</source>
        <translation>Die Maschine in Ruhe</translation>
    </message>
</context>
<context>
    <name>StateNames</name>
    <message>
        <source>Stop in initial state</source>
        <translation>Halt im Anfangszustand</translation>
    </message>
    <message>
        <source>Stop requested at end of cycle</source>
        <translation>Angeforderter Halt am Zyklusende</translation>
    </message>
    <message>
        <source>Stop requested in a given state</source>
        <translation>Angeforderter Halt in einem bestimmten Zustand</translation>
    </message>
    <message>
        <source>Stop obtained</source>
        <translation>Erreichter Halt</translation>
    </message>
    <message>
        <source>Preparation for restart after failure</source>
        <translation>Vorbereitung für den Wiederanlauf nach Störung</translation>
    </message>
    <message>
        <source>Operative part reset to initial state</source>
        <translation>Rücksetzen des Prozesses in den Anfangszustand</translation>
    </message>
    <message>
        <source>Operative part set to a given state</source>
        <translation>Setzen des Prozesses in einen bestimmten Zustand</translation>
    </message>
    <message>
        <source>Normal production</source>
        <translation>Normalbetrieb</translation>
    </message>
    <message>
        <source>Preparation run</source>
        <translation>Vorbereitungsbetrieb</translation>
    </message>
    <message>
        <source>Closing run</source>
        <translation>Abschlussbetrieb</translation>
    </message>
    <message>
        <source>Verification run out of order</source>
        <translation>Prüfbetrieb ohne Reihenfolge</translation>
    </message>
    <message>
        <source>Verification run in order</source>
        <translation>Prüfbetrieb in Reihenfolge</translation>
    </message>
    <message>
        <source>Test run</source>
        <translation>Testbetrieb</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Not-Halt</translation>
    </message>
    <message>
        <source>Diagnosis and/or failure handling</source>
        <translation>Diagnose und/oder Störungsbehandlung</translation>
    </message>
    <message>
        <source>Production despite failure</source>
        <translation>Produktion trotz Störung</translation>
    </message>
    <message>
        <source>Stop procedures</source>
        <translation>Stoppverfahren</translation>
    </message>
    <message>
        <source>Operation procedures</source>
        <translation>Betriebsverfahren</translation>
    </message>
    <message>
        <source>Failure procedures</source>
        <translation>Störungsverfahren</translation>
    </message>
</context>
<context>
    <name>ValueProblemText</name>
    <message>
        <source>&apos;%1&apos; is not an %2 literal: write a whole number such as 42</source>
        <extracomment>%1: the value as written; %2: INT</extracomment>
        <translation>&apos;%1&apos; ist kein %2-Literal: eine ganze Zahl wie 42 schreiben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a %2 literal: write a whole number such as 42</source>
        <extracomment>%1: the value as written; %2: an integer type other than INT (SINT, UDINT...)</extracomment>
        <translation>&apos;%1&apos; ist kein %2-Literal: eine ganze Zahl wie 42 schreiben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has leading or trailing spaces</source>
        <translation>&apos;%1&apos; hat Leerzeichen am Anfang oder am Ende</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a BOOL literal (TRUE or FALSE)</source>
        <translation>&apos;%1&apos; ist kein BOOL-Literal (TRUE oder FALSE)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a %2 literal: write a decimal number such as 1.5 or 2.0E3</source>
        <extracomment>%1: the value as written; %2: REAL or LREAL</extracomment>
        <translation>&apos;%1&apos; ist kein %2-Literal: eine Dezimalzahl wie 1.5 oder 2.0E3 schreiben</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range for %2 (%3..%4)</source>
        <extracomment>%1: the value as written; %2: its IEC type; %3..%4: the type&apos;s range</extracomment>
        <translation>&apos;%1&apos; liegt außerhalb des Wertebereichs von %2 (%3..%4)</translation>
    </message>
</context>
<context>
    <name>editor::Autosave</name>
    <message>
        <source>Cannot create the folder %1 for recovery copies</source>
        <translation>Der Ordner %1 für Wiederherstellungskopien kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>Cannot write the recovery copy: %1</source>
        <translation>Die Wiederherstellungskopie kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>Cannot lock the recovery copy %1</source>
        <translation>Die Wiederherstellungskopie %1 kann nicht gesperrt werden</translation>
    </message>
    <message>
        <source>Another GG Studio is using the recovery copy %1.</source>
        <translation>Eine andere GG-Studio-Instanz verwendet die Wiederherstellungskopie %1.</translation>
    </message>
</context>
<context>
    <name>editor::BranchDrag</name>
    <message>
        <source>Step %1 is on no branch of a divergence: there is no branch to move</source>
        <translation>Schritt %1 liegt auf keinem Zweig einer Verzweigung: es gibt keinen Zweig zu verschieben</translation>
    </message>
    <message>
        <source>Move the branch of step %1 left in %2</source>
        <translation>Zweig von Schritt %1 in %2 nach links verschieben</translation>
    </message>
    <message>
        <source>Move the branch of step %1 right in %2</source>
        <translation>Zweig von Schritt %1 in %2 nach rechts verschieben</translation>
    </message>
</context>
<context>
    <name>editor::ChartContextMenu</name>
    <message>
        <source>&amp;Show %1</source>
        <translation>%1 &amp;einblenden</translation>
    </message>
    <message>
        <source>&amp;Hide %1</source>
        <translation>%1 &amp;ausblenden</translation>
    </message>
    <message>
        <source>Step &amp;Type</source>
        <translation>Schritt&amp;typ</translation>
    </message>
    <message>
        <source>Make &amp;Initial Step</source>
        <translation>Zum &amp;Anfangsschritt machen</translation>
    </message>
    <message>
        <source>Edit &amp;Comment…</source>
        <translation>&amp;Kommentar bearbeiten…</translation>
    </message>
    <message>
        <source>Edit &amp;Condition…</source>
        <translation>&amp;Bedingung bearbeiten…</translation>
    </message>
    <message>
        <source>&amp;Negated</source>
        <translation>&amp;Negiert</translation>
    </message>
    <message>
        <source>Flips whether this transition waits for Complete of its source&apos;s nested behaviour</source>
        <translation>Kehrt um, ob diese Transition auf Complete des eingebetteten Verhaltens ihres Quellschritts wartet</translation>
    </message>
    <message>
        <source>Priority &amp;Up</source>
        <translation>Priorität &amp;erhöhen</translation>
    </message>
    <message>
        <source>Priority &amp;Down</source>
        <translation>Priorität &amp;senken</translation>
    </message>
    <message numerus="yes">
        <source>Hide the %n Selected Elements</source>
        <translation>
            <numerusform>Das ausgewählte Element ausblenden</numerusform>
            <numerusform>Die %n ausgewählten Elemente ausblenden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show the %n Selected Elements</source>
        <translation>
            <numerusform>Das ausgewählte Element einblenden</numerusform>
            <numerusform>Die %n ausgewählten Elemente einblenden</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Open Nested GRAFCET</source>
        <translation>Eingebetteten GRAFCET ö&amp;ffnen</translation>
    </message>
</context>
<context>
    <name>editor::ConditionList</name>
    <message>
        <source>[%1] %2: %3</source>
        <extracomment>an entry of the Conditions list under an exported chart: note number, transition, its condition in full</extracomment>
        <translation>[%1] %2: %3</translation>
    </message>
    <message>
        <source>Conditions</source>
        <translation>Bedingungen</translation>
    </message>
</context>
<context>
    <name>editor::ConnectTransitionDialog</name>
    <message>
        <source>Connect T%1 of %2</source>
        <extracomment>%1 the transition&apos;s number, %2 the GEMMA step whose GRAFCET it is in</extracomment>
        <translation>T%1 von %2 verbinden</translation>
    </message>
    <message>
        <source>Upstream steps (it leaves them)</source>
        <translation>Vorgängerschritte (sie deaktiviert sie)</translation>
    </message>
    <message>
        <source>Downstream steps (it activates them)</source>
        <translation>Nachfolgerschritte (sie aktiviert sie)</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <source>Tick an upstream step: a transition leaves at least one step.</source>
        <translation>Haken Sie einen vorangehenden Schritt an: eine Transition verlässt mindestens einen Schritt.</translation>
    </message>
    <message>
        <source>Tick a downstream step: a transition activates at least one step. To end a branch on a step with no transition after it, use Add Branch Ending on a Step on the step.</source>
        <translation>Haken Sie einen nachfolgenden Schritt an: eine Transition aktiviert mindestens einen Schritt. Um einen Zweig auf einem Schritt ohne Transition danach enden zu lassen, verwenden Sie „Zweig mit Endschritt hinzufügen“ auf dem Schritt.</translation>
    </message>
</context>
<context>
    <name>editor::Document</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Stop the simulation to edit the model</source>
        <translation>Beenden Sie die Simulation, um das Modell zu bearbeiten</translation>
    </message>
</context>
<context>
    <name>editor::ExportActions</name>
    <message>
        <source>Export &amp;PLCopen XML…</source>
        <translation>&amp;PLCopen XML exportieren…</translation>
    </message>
    <message>
        <source>Write the PLC program as PLCopen XML, to import into a PLC programming tool</source>
        <translation>Das SPS-Programm als PLCopen XML schreiben, zum Import in ein SPS-Programmierwerkzeug</translation>
    </message>
    <message>
        <source>Export &amp;Structured Text…</source>
        <translation>Strukturierten &amp;Text (ST) exportieren…</translation>
    </message>
    <message>
        <source>Write the PLC program as IEC 61131-3 Structured Text files</source>
        <translation>Das SPS-Programm als Dateien in Strukturiertem Text (ST) nach IEC 61131-3 schreiben</translation>
    </message>
    <message>
        <source>Export &amp;GG-Generator JSON…</source>
        <translation>&amp;GG-Generator-JSON exportieren…</translation>
    </message>
    <message>
        <source>Save the model in the format of the GG-Generator web tool</source>
        <translation>Das Modell im Format des Webwerkzeugs GG-Generator speichern</translation>
    </message>
    <message>
        <source>Export &amp;Chart…</source>
        <translation>Diagramm &amp;exportieren…</translation>
    </message>
    <message>
        <source>Save the chart as an SVG, PNG or PDF picture</source>
        <translation>Das Diagramm als SVG-, PNG- oder PDF-Bild speichern</translation>
    </message>
    <message>
        <source>&amp;Print…</source>
        <translation>&amp;Drucken…</translation>
    </message>
    <message>
        <source>Print the chart</source>
        <translation>Das Diagramm drucken</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… und %n weiterer</numerusform>
            <numerusform>… und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <source>Export a Model with Errors</source>
        <translation>Modell mit Fehlern exportieren</translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s). The generated code marks each one with a comment, but it may not compile or may not behave as intended.</source>
        <translation>
            <numerusform>Das Modell hat %n Fehler. Der generierte Code markiert ihn mit einem Kommentar, lässt sich aber möglicherweise nicht übersetzen oder verhält sich nicht wie beabsichtigt.</numerusform>
            <numerusform>Das Modell hat %n Fehler. Der generierte Code markiert jeden mit einem Kommentar, lässt sich aber möglicherweise nicht übersetzen oder verhält sich nicht wie beabsichtigt.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Export Anyway</source>
        <translation>&amp;Trotzdem exportieren</translation>
    </message>
    <message>
        <source>Export PLCopen XML</source>
        <translation>PLCopen XML exportieren</translation>
    </message>
    <message>
        <source>PLCopen XML (*.xml)</source>
        <translation>PLCopen XML (*.xml)</translation>
    </message>
    <message>
        <source>Export Structured Text</source>
        <translation>Strukturierten Text exportieren</translation>
    </message>
    <message>
        <source>Structured Text (*.st)</source>
        <translation>Strukturierter Text (*.st)</translation>
    </message>
    <message>
        <source>Export Structured Text to a Folder</source>
        <translation>Strukturierten Text in einen Ordner exportieren</translation>
    </message>
    <message>
        <source>Export GG-Generator JSON</source>
        <translation>GG-Generator-JSON exportieren</translation>
    </message>
    <message>
        <source>GG-Generator JSON (*.json)</source>
        <translation>GG-Generator-JSON (*.json)</translation>
    </message>
    <message>
        <source>SVG picture (*.svg)</source>
        <translation>SVG-Bild (*.svg)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <source>Export Chart</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <source>Print Chart</source>
        <translation>Diagramm drucken</translation>
    </message>
    <message>
        <source>The printer could not be started.</source>
        <translation>Der Drucker konnte nicht gestartet werden.</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>Exportiert nach %1</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>%1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>The nested GRAFCETs of %1: GG-Generator has no place for nested behaviour.</source>
        <translation>Die eingebetteten GRAFCETs von %1: GG-Generator kann kein eingebettetes Verhalten aufnehmen.</translation>
    </message>
    <message>
        <source>The variable kinds (output, internal): GG-Generator reads every variable as an input.</source>
        <translation>Die Variablenarten (Ausgang, intern): GG-Generator liest jede Variable als Eingang.</translation>
    </message>
    <message>
        <source>The until-stable evolution rule: GG-Generator knows one evolution per scan only.</source>
        <translation>Die Entwicklungsregel „bis stabil“: GG-Generator kennt nur eine Entwicklung pro Zyklus.</translation>
    </message>
    <message>
        <source>Export to GG-Generator</source>
        <translation>Nach GG-Generator exportieren</translation>
    </message>
    <message>
        <source>The GG-Generator file will leave out part of this model. Your model and its own file keep everything.</source>
        <translation>Die GG-Generator-Datei lässt einen Teil dieses Modells weg. Ihr Modell und seine eigene Datei behalten alles.</translation>
    </message>
    <message>
        <source>%1, nested GRAFCET of %2</source>
        <translation>%1, eingebetteter GRAFCET von %2</translation>
    </message>
    <message>
        <source>Export Speci&amp;fication…</source>
        <translation>Spezifi&amp;kation exportieren…</translation>
    </message>
    <message>
        <source>Write the whole model as one PDF document: the chart, the states, the variables, every nested GRAFCET and the outline of the generated code</source>
        <translation>Das ganze Modell als ein PDF-Dokument schreiben: das Diagramm, die Zustände, die Variablen, jeden eingebetteten GRAFCET und die Übersicht des erzeugten Codes</translation>
    </message>
    <message>
        <source>Export Specification</source>
        <translation>Spezifikation exportieren</translation>
    </message>
    <message>
        <source>The verification properties: GG-Generator has no place for them.</source>
        <translation>Die Verifikationseigenschaften: GG-Generator hat keinen Platz dafür.</translation>
    </message>
    <message>
        <source>Writing the specification…</source>
        <translation>Die Spezifikation wird geschrieben…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Export cancelled: %1 left unchanged</source>
        <translation>Export abgebrochen: %1 bleibt unverändert</translation>
    </message>
</context>
<context>
    <name>editor::ExportOptionsDialog</name>
    <message>
        <source>Export PLCopen XML</source>
        <translation>PLCopen XML exportieren</translation>
    </message>
    <message>
        <source>Export Structured Text</source>
        <translation>Strukturierten Text exportieren</translation>
    </message>
    <message>
        <source>One file per POU, in a &amp;folder</source>
        <translation>Eine Datei je POE, in einem &amp;Ordner</translation>
    </message>
    <message>
        <source>One &amp;IEC 61131-3 file with every POU</source>
        <translation>Eine &amp;IEC-61131-3-Datei mit allen POEs</translation>
    </message>
    <message>
        <source>Files:</source>
        <translation>Dateien:</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialekt:</translation>
    </message>
    <message>
        <source>IEC writes PLCopen TC6 XML 2.01 with the globals in the configuration. CODESYS writes what CODESYS V3.5 imports, with a GVL.</source>
        <translation>IEC schreibt PLCopen TC6 XML 2.01 mit den globalen Variablen in der Konfiguration. CODESYS schreibt, was CODESYS V3.5 importiert, mit einer GVL.</translation>
    </message>
    <message>
        <source>The single file is always IEC 61131-3: CODESYS code names a GVL that IEC compilers do not know.</source>
        <translation>Die einzelne Datei ist immer IEC 61131-3: CODESYS-Code verweist auf eine GVL, die IEC-Compiler nicht kennen.</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportieren…</translation>
    </message>
    <message>
        <source>IEC 61131-3 (Beremiz, OpenPLC, TwinCAT…)</source>
        <translation>IEC 61131-3 (Beremiz, OpenPLC, TwinCAT…)</translation>
    </message>
    <message>
        <source>CODESYS</source>
        <translation>CODESYS</translation>
    </message>
</context>
<context>
    <name>editor::FrameItem</name>
    <message>
        <source>%1 — %2</source>
        <extracomment>Title of a GEMMA family frame: %1 is the letter (A, F, D), %2 the family name</extracomment>
        <translation>%1 — %2</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetActions</name>
    <message>
        <source>Insert Step &amp;After</source>
        <translation>Schritt &amp;danach einfügen</translation>
    </message>
    <message>
        <source>Insert Step &amp;Before</source>
        <translation>Schritt da&amp;vor einfügen</translation>
    </message>
    <message>
        <source>Add &amp;Selection Branch</source>
        <translation>Alternativ&amp;zweig hinzufügen</translation>
    </message>
    <message>
        <source>Add &amp;Parallel Branch</source>
        <translation>&amp;Parallelzweig hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <source>Remove Bra&amp;nch</source>
        <translation>&amp;Zweig entfernen</translation>
    </message>
    <message>
        <source>Ren&amp;umber Steps and Transitions</source>
        <translation>Schritte und Transitionen &amp;umnummerieren</translation>
    </message>
    <message>
        <source>&amp;Connect Directly…</source>
        <translation>Direkt &amp;verbinden…</translation>
    </message>
    <message>
        <source>&amp;Copy Steps</source>
        <translation>Schritte &amp;kopieren</translation>
    </message>
    <message>
        <source>&amp;Paste Steps</source>
        <translation>Schritte ein&amp;fügen</translation>
    </message>
    <message>
        <source>Create the &amp;Usual Shape</source>
        <translation>Übliche &amp;Form erstellen</translation>
    </message>
    <message>
        <source>Initial step 1, then step 2, then step 3, which sets Complete</source>
        <translation>Anfangsschritt 1, dann Schritt 2, dann Schritt 3, der Complete setzt</translation>
    </message>
    <message>
        <source>%1 has no GRAFCET yet.&lt;br&gt;&lt;a href=&quot;create&quot;&gt;Create the usual shape&lt;/a&gt;: initial step 1, step 2, and step 3, which sets Complete.</source>
        <extracomment>%1 the GEMMA step; the link creates its GRAFCET</extracomment>
        <translation>%1 hat noch keinen GRAFCET.&lt;br&gt;&lt;a href=&quot;create&quot;&gt;Übliche Form erstellen&lt;/a&gt;: Anfangsschritt 1, Schritt 2 und Schritt 3, der Complete setzt.</translation>
    </message>
    <message>
        <source>Add Loop or &amp;Jump To</source>
        <translation>Schleife oder &amp;Sprung hinzufügen zu</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <source>Add step %1 to %2</source>
        <translation>Schritt %1 zu %2 hinzufügen</translation>
    </message>
    <message>
        <source>Add selection branch to %1</source>
        <translation>Alternativzweig zu %1 hinzufügen</translation>
    </message>
    <message>
        <source>Add parallel branch to %1</source>
        <translation>Parallelzweig zu %1 hinzufügen</translation>
    </message>
    <message>
        <source>Add jump from step %1 to step %2 in %3</source>
        <extracomment>%1 and %2 step numbers, %3 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Sprung von Schritt %1 zu Schritt %2 in %3 hinzufügen</translation>
    </message>
    <message>
        <source>Remove step %1 from %2</source>
        <translation>Schritt %1 aus %2 entfernen</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n steps from %1</source>
        <translation>
            <numerusform>%n Schritt aus %1 entfernen</numerusform>
            <numerusform>%n Schritte aus %1 entfernen</numerusform>
        </translation>
    </message>
    <message>
        <source>Remove branch from %1</source>
        <translation>Zweig aus %1 entfernen</translation>
    </message>
    <message>
        <source>Renumber %1</source>
        <translation>%1 umnummerieren</translation>
    </message>
    <message>
        <source>Connect %1 T%2</source>
        <extracomment>%1 the GEMMA step, %2 the transition&apos;s number</extracomment>
        <translation>%1 T%2 verbinden</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n steps into %1</source>
        <translation>
            <numerusform>%n Schritt in %1 einfügen</numerusform>
            <numerusform>%n Schritte in %1 einfügen</numerusform>
        </translation>
    </message>
    <message>
        <source>Create GRAFCET of %1</source>
        <translation>GRAFCET von %1 erstellen</translation>
    </message>
    <message>
        <source>Add Branch &amp;Ending on a Step</source>
        <translation>Zweig mit &amp;Endschritt hinzufügen</translation>
    </message>
    <message>
        <source>A new branch from this step to a new step with no transition after it (an exit step)</source>
        <translation>Ein neuer Zweig von diesem Schritt zu einem neuen Schritt ohne Transition danach (ein Endschritt)</translation>
    </message>
    <message>
        <source>Move Branch &amp;Left</source>
        <translation>Zweig nach &amp;links verschieben</translation>
    </message>
    <message>
        <source>Swap the branch holding this step with the one at its left</source>
        <translation>Tauscht den Zweig mit diesem Schritt mit dem links daneben</translation>
    </message>
    <message>
        <source>Move Branch Ri&amp;ght</source>
        <translation>Zweig nach &amp;rechts verschieben</translation>
    </message>
    <message>
        <source>Swap the branch holding this step with the one at its right</source>
        <translation>Tauscht den Zweig mit diesem Schritt mit dem rechts daneben</translation>
    </message>
    <message>
        <source>Cu&amp;t Steps</source>
        <translation>Schritte &amp;ausschneiden</translation>
    </message>
    <message>
        <source>Add branch ending on a step at step %1 in %2</source>
        <extracomment>%1 the step the branch leaves, %2 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Zweig mit Endschritt an Schritt %1 in %2 hinzufügen</translation>
    </message>
    <message>
        <source>Move branch left in %1</source>
        <extracomment>%1 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Zweig in %1 nach links verschieben</translation>
    </message>
    <message>
        <source>Move branch right in %1</source>
        <translation>Zweig in %1 nach rechts verschieben</translation>
    </message>
    <message>
        <source>Remove T%1 from %2</source>
        <translation>T%1 aus %2 entfernen</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n transitions from %1</source>
        <translation>
            <numerusform>%n Transition aus %1 entfernen</numerusform>
            <numerusform>%n Transitionen aus %1 entfernen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remove %n elements from %1</source>
        <translation>
            <numerusform>%n Element aus %1 entfernen</numerusform>
            <numerusform>%n Elemente aus %1 entfernen</numerusform>
        </translation>
    </message>
    <message>
        <source>Cut step %1 from %2</source>
        <translation>Schritt %1 aus %2 ausschneiden</translation>
    </message>
    <message numerus="yes">
        <source>Cut %n steps from %1</source>
        <translation>
            <numerusform>%n Schritt aus %1 ausschneiden</numerusform>
            <numerusform>%n Schritte aus %1 ausschneiden</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::GrafcetActionsModel</name>
    <message>
        <source>When</source>
        <translation>Wann</translation>
    </message>
    <message>
        <source>Qual.</source>
        <extracomment>short: the column is narrow; its tooltip says &quot;qualifier&quot; in full</extracomment>
        <translation>Best.</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>IF / value</source>
        <extracomment>the condition after IF of an N action, or the value of a := action; short: the column is narrow</extracomment>
        <translation>IF / Wert</translation>
    </message>
    <message>
        <source>While the step is active (N), or once when it is activated or deactivated (S, R, :=)</source>
        <translation>Solange der Schritt aktiv ist (N), oder einmal bei seiner Aktivierung oder Deaktivierung (S, R, :=)</translation>
    </message>
    <message>
        <source>Qualifier. N: the variable is TRUE while the step is active
S, R: set it TRUE or FALSE
:=: assign it the value</source>
        <translation>Bestimmungszeichen. N: die Variable ist TRUE, solange der Schritt aktiv ist
S, R: auf TRUE oder FALSE setzen
:=: ihr den Wert zuweisen</translation>
    </message>
    <message>
        <source>An output or internal variable, or Complete</source>
        <translation>Eine Ausgangs- oder interne Variable, oder Complete</translation>
    </message>
    <message>
        <source>N: only IF this condition holds (may be empty)
:=: the value assigned</source>
        <translation>N: nur IF diese Bedingung gilt (darf leer sein)
:=: der zugewiesene Wert</translation>
    </message>
    <message>
        <source>While active</source>
        <translation>Solange aktiv</translation>
    </message>
    <message>
        <source>On activation</source>
        <translation>Bei Aktivierung</translation>
    </message>
    <message>
        <source>On deactivation</source>
        <translation>Bei Deaktivierung</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetSimulationMarks</name>
    <message>
        <source>%1 is active: its GRAFCET runs. Unstable: the last scan ended without a stable situation</source>
        <translation>%1 ist aktiv: sein GRAFCET läuft. Unstable: der letzte Zyklus endete ohne stabile Situation</translation>
    </message>
    <message>
        <source>%1 has just been entered: its GRAFCET starts from its initial steps in the next scan</source>
        <translation>%1 wurde gerade aktiviert: sein GRAFCET beginnt im nächsten Zyklus mit seinen Anfangsschritten</translation>
    </message>
    <message>
        <source>%1 is not active: its GRAFCET is shown greyed, as it was left</source>
        <translation>%1 ist nicht aktiv: sein GRAFCET wird grau gezeigt, so wie er verlassen wurde</translation>
    </message>
    <message numerus="yes">
        <source>%1 is active: its GRAFCET runs (step(s) %2)</source>
        <translation>
            <numerusform>%1 ist aktiv: sein GRAFCET läuft (Schritt %2)</numerusform>
            <numerusform>%1 ist aktiv: sein GRAFCET läuft (Schritte %2)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 has just been resumed: its GRAFCET goes on where it was paused in the next scan</source>
        <translation>%1 wurde gerade fortgesetzt: sein GRAFCET macht im nächsten Zyklus dort weiter, wo es angehalten wurde</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetStepDock</name>
    <message>
        <source>Nested Step</source>
        <translation>Eingebetteter Schritt</translation>
    </message>
    <message>
        <source>Select a step in a nested GRAFCET&apos;s tab to see and edit its number, comment and actions.</source>
        <translation>Wählen Sie einen Schritt im Tab eines eingebetteten GRAFCET, um seine Nummer, seinen Kommentar und seine Aktionen zu sehen und zu bearbeiten.</translation>
    </message>
    <message>
        <source>&amp;Number:</source>
        <translation>&amp;Nummer:</translation>
    </message>
    <message>
        <source>Unique in this GRAFCET; its activity is X&lt;number&gt;. The transitions and the X&lt;number&gt; of the receptivities and actions follow a new number.</source>
        <translation>Eindeutig in diesem GRAFCET; seine Aktivität ist X&lt;Nummer&gt;. Die Transitionen und die X&lt;Nummer&gt; der Weiterschaltbedingungen und Aktionen folgen einer neuen Nummer.</translation>
    </message>
    <message>
        <source>&amp;Initial</source>
        <translation>&amp;Anfangsschritt</translation>
    </message>
    <message>
        <source>Active when the GEMMA state is entered (a GRAFCET needs at least one)</source>
        <translation>Aktiv, wenn der GEMMA-Zustand betreten wird (ein GRAFCET braucht mindestens einen)</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Kommentar:</translation>
    </message>
    <message>
        <source>What the machine does in this step</source>
        <translation>Was die Maschine in diesem Schritt tut</translation>
    </message>
    <message>
        <source>&amp;Actions:</source>
        <translation>A&amp;ktionen:</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Add an action after the current one</source>
        <translation>Eine Aktion nach der aktuellen hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Remove the current action</source>
        <translation>Die aktuelle Aktion entfernen</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Auf</translation>
    </message>
    <message>
        <source>Run the current action earlier</source>
        <translation>Die aktuelle Aktion früher ausführen</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Ab</translation>
    </message>
    <message>
        <source>Run the current action later</source>
        <translation>Die aktuelle Aktion später ausführen</translation>
    </message>
    <message>
        <source>%1 step %2</source>
        <extracomment>A step of the nested GRAFCET of a GEMMA step: &quot;F1 step 3&quot;</extracomment>
        <translation>%1 Schritt %2</translation>
    </message>
    <message>
        <source>In the nested GRAFCET of %1 %2</source>
        <translation>Im eingebetteten GRAFCET von %1 %2</translation>
    </message>
    <message>
        <source>%1 already has a step %2: choose another number.</source>
        <translation>%1 hat schon einen Schritt %2: wählen Sie eine andere Nummer.</translation>
    </message>
    <message>
        <source>Step numbers start at 1: %1 is not a step number.</source>
        <translation>Schrittnummern beginnen bei 1: %1 ist keine Schrittnummer.</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetTabs</name>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>The GRAFCET of %1 in the mode %2</source>
        <translation>Das GRAFCET von %1 in der Betriebsart %2</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1</source>
        <translation>Der eingebettete GRAFCET von %1</translation>
    </message>
    <message>
        <source>PackML Chart</source>
        <translation>PackML-Diagramm</translation>
    </message>
    <message>
        <source>GEMMA Chart</source>
        <translation>GEMMA-Diagramm</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetTransitionDock</name>
    <message>
        <source>Nested Transition</source>
        <translation>Eingebettete Transition</translation>
    </message>
    <message>
        <source>Select a transition in a nested GRAFCET&apos;s tab to see and edit its receptivity.</source>
        <translation>Wählen Sie eine Transition im Tab eines eingebetteten GRAFCET, um ihre Weiterschaltbedingung zu sehen und zu bearbeiten.</translation>
    </message>
    <message>
        <source>From steps:</source>
        <translation>Von den Schritten:</translation>
    </message>
    <message>
        <source>To steps:</source>
        <translation>Zu den Schritten:</translation>
    </message>
    <message>
        <source>Click a step to select it</source>
        <translation>Klicken Sie auf einen Schritt, um ihn auszuwählen</translation>
    </message>
    <message>
        <source>&amp;Receptivity:</source>
        <translation>&amp;Weiterschaltbedingung:</translation>
    </message>
    <message>
        <source>e.g. PartPresent AND X3, ↑Start, 5s/X2</source>
        <translation>z. B. PartPresent AND X3, ↑Start, 5s/X2</translation>
    </message>
    <message>
        <source>Structured Text as in GEMMA conditions, plus X3 (step 3 is active), ↑a or RE a (rising edge), ↓a or FE a (falling edge), 5s/X3 (step 3 active for 5 s) and Complete.
Ctrl+Space completes a name.</source>
        <translation>Strukturierter Text wie in den GEMMA-Bedingungen, dazu X3 (Schritt 3 ist aktiv), ↑a oder RE a (steigende Flanke), ↓a oder FE a (fallende Flanke), 5s/X3 (Schritt 3 seit 5 s aktiv) und Complete.
Strg+Leertaste vervollständigt einen Namen.</translation>
    </message>
    <message>
        <source>%1 T%2</source>
        <extracomment>A transition of the nested GRAFCET of a GEMMA step: &quot;F1 T2&quot;</extracomment>
        <translation>%1 T%2</translation>
    </message>
    <message>
        <source>In the nested GRAFCET of %1 %2</source>
        <translation>Im eingebetteten GRAFCET von %1 %2</translation>
    </message>
</context>
<context>
    <name>editor::LinkDrag</name>
    <message>
        <source>A transition cannot be linked to a transition: steps and transitions alternate</source>
        <translation>Eine Transition kann nicht mit einer Transition verbunden werden: Schritte und Transitionen wechseln sich ab</translation>
    </message>
    <message>
        <source>Step %1 already leads to step %2</source>
        <translation>Schritt %1 führt bereits zu Schritt %2</translation>
    </message>
    <message>
        <source>Step %1 already precedes T%2</source>
        <translation>Schritt %1 steht bereits vor T%2</translation>
    </message>
    <message>
        <source>Step %1 already follows T%2</source>
        <translation>Schritt %1 folgt bereits auf T%2</translation>
    </message>
    <message>
        <source>Step %1 cannot be linked to itself through one transition</source>
        <translation>Schritt %1 kann nicht über eine einzige Transition mit sich selbst verbunden werden</translation>
    </message>
    <message>
        <source>Step %1 would be linked to itself through T%2</source>
        <translation>Schritt %1 wäre über T%2 mit sich selbst verbunden</translation>
    </message>
    <message>
        <source>Drag onto a step or a transition to link them</source>
        <translation>Auf einen Schritt oder eine Transition ziehen, um beide zu verbinden</translation>
    </message>
    <message>
        <source>Link step %1 to step %2 in %3</source>
        <translation>Schritt %1 mit Schritt %2 in %3 verbinden</translation>
    </message>
    <message>
        <source>Link step %1 to T%2 in %3</source>
        <translation>Schritt %1 mit T%2 in %3 verbinden</translation>
    </message>
    <message>
        <source>Link T%1 to step %2 in %3</source>
        <translation>T%1 mit Schritt %2 in %3 verbinden</translation>
    </message>
</context>
<context>
    <name>editor::MachineDock</name>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Add a component of the kind chosen beside</source>
        <translation>Eine Komponente der daneben gewählten Art hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Remove the selected component and its wiring</source>
        <translation>Die gewählte Komponente und ihre Verdrahtung entfernen</translation>
    </message>
    <message>
        <source>The model has no machine yet. Add its components to simulate in closed loop: the machine then sets the sensors.</source>
        <translation>Das Modell hat noch keine Maschine. Fügen Sie ihre Komponenten hinzu, um im geschlossenen Regelkreis zu simulieren: die Maschine setzt dann die Sensoren.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>(not wired)</source>
        <translation>(nicht verdrahtet)</translation>
    </message>
    <message>
        <source>A BOOL output of the program, which drives the component</source>
        <translation>Ein BOOL-Ausgang des Programms, der die Komponente ansteuert</translation>
    </message>
    <message>
        <source>A BOOL input of the program, which the component sets</source>
        <translation>Ein BOOL-Eingang des Programms, den die Komponente setzt</translation>
    </message>
    <message>
        <source>Unlimited</source>
        <translation>Unbegrenzt</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keiner)</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>Speist</translation>
    </message>
</context>
<context>
    <name>editor::MachineTab</name>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>The virtual machine: its components, moving as the simulation runs</source>
        <translation>Die virtuelle Maschine: ihre Komponenten, die sich während der Simulation bewegen</translation>
    </message>
</context>
<context>
    <name>editor::MainWindow</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatische Sicherung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>Start a new model from the GEMMA template</source>
        <translation>Ein neues Modell aus der GEMMA-Vorlage beginnen</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Öffnen…</translation>
    </message>
    <message>
        <source>Open a GG Studio model, a GG-Generator file or an exported PLCopen XML file</source>
        <translation>Ein GG-Studio-Modell, eine GG-Generator-Datei oder eine exportierte PLCopen-XML-Datei öffnen</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>&amp;Reset to Template…</source>
        <translation>&amp;Auf Vorlage zurücksetzen…</translation>
    </message>
    <message>
        <source>Put every state, transition, variable and setting back to the template</source>
        <translation>Alle Zustände, Transitionen, Variablen und Einstellungen auf die Vorlage zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederherstellen: %1</translation>
    </message>
    <message>
        <source>&amp;Model Settings…</source>
        <translation>&amp;Modelleinstellungen…</translation>
    </message>
    <message>
        <source>Model name, PLC cycle time and code dialect</source>
        <translation>Modellname, SPS-Zykluszeit und Code-Dialekt</translation>
    </message>
    <message>
        <source>Show &amp;Hidden Elements</source>
        <translation>&amp;Ausgeblendete Elemente anzeigen</translation>
    </message>
    <message>
        <source>Draw the hidden states and transitions faded, so they can be selected</source>
        <translation>Die ausgeblendeten Zustände und Transitionen blass zeichnen, damit sie ausgewählt werden können</translation>
    </message>
    <message>
        <source>&amp;Actual Size (100 %)</source>
        <translation>&amp;Originalgröße (100 %)</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <source>&amp;About GG Studio</source>
        <translation>Über &amp;GG Studio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>%1[*] — GG Studio</source>
        <translation>%1[*] — GG Studio</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The model “%1” has unsaved changes.</source>
        <translation>Das Modell „%1“ hat ungespeicherte Änderungen.</translation>
    </message>
    <message>
        <source>Do you want to save them?</source>
        <translation>Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <source>All supported files (*.json *.xml)</source>
        <translation>Alle unterstützten Dateien (*.json *.xml)</translation>
    </message>
    <message>
        <source>GG Studio models (*.json)</source>
        <translation>GG-Studio-Modelle (*.json)</translation>
    </message>
    <message>
        <source>GG-Generator files (*.json)</source>
        <translation>GG-Generator-Dateien (*.json)</translation>
    </message>
    <message>
        <source>GG Studio PLCopen XML (*.xml)</source>
        <translation>GG Studio PLCopen XML (*.xml)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Open Model</source>
        <translation>Modell öffnen</translation>
    </message>
    <message>
        <source>Could not open %1.</source>
        <translation>%1 konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Imported %1: Save As keeps it as a GG Studio model</source>
        <translation>%1 importiert: „Speichern unter“ legt es als GG-Studio-Modell ab</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>Save Model As</source>
        <translation>Modell speichern unter</translation>
    </message>
    <message>
        <source>Save Model</source>
        <translation>Modell speichern</translation>
    </message>
    <message>
        <source>Could not save %1.</source>
        <translation>%1 konnte nicht gespeichert werden.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>%1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Recovered unsaved changes: save them to keep them</source>
        <translation>Ungespeicherte Änderungen wiederhergestellt: Speichern Sie sie, um sie zu behalten</translation>
    </message>
    <message>
        <source>Reset to Template</source>
        <translation>Auf Vorlage zurücksetzen</translation>
    </message>
    <message>
        <source>Put every state, transition, variable and setting back to the GEMMA template? You can undo this.</source>
        <translation>Alle Zustände, Transitionen, Variablen und Einstellungen auf die GEMMA-Vorlage zurücksetzen? Dies lässt sich rückgängig machen.</translation>
    </message>
    <message>
        <source>About GG Studio</source>
        <translation>Über GG Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;GG Studio %1&lt;/h3&gt;&lt;p&gt;An editor for the GEMMA-GRAFCET method: choose the operating modes of a machine on the GEMMA template, write the conditions of their transitions, and generate the IEC 61131-3 program that runs them (Structured Text, PLCopen XML).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;GG Studio %1&lt;/h3&gt;&lt;p&gt;Ein Editor für die GEMMA-GRAFCET-Methode: Wählen Sie die Betriebsarten einer Maschine auf der GEMMA-Vorlage, schreiben Sie die Bedingungen ihrer Transitionen und erzeugen Sie das Programm nach IEC 61131-3, das sie ausführt (Strukturierter Text, PLCopen XML).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Simulate</source>
        <translation>&amp;Simulieren</translation>
    </message>
    <message>
        <source>Run the model scan by scan; editing is locked while the simulation is on</source>
        <translation>Das Modell Zyklus für Zyklus ausführen; während der Simulation ist das Bearbeiten gesperrt</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Ausführen</translation>
    </message>
    <message>
        <source>Run scans at the speed set in the Simulation dock, or pause them</source>
        <translation>Zyklen mit der im Fenster Simulation eingestellten Geschwindigkeit ausführen oder anhalten</translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation>&amp;Einzelner Zyklus</translation>
    </message>
    <message>
        <source>R&amp;eset Simulation</source>
        <translation>Simulation &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Simulation: editing locked</source>
        <translation>Simulation: Bearbeiten gesperrt</translation>
    </message>
    <message>
        <source>&amp;Verify</source>
        <translation>&amp;Verifizieren</translation>
    </message>
    <message>
        <source>Verifying…</source>
        <translation>Verifikation läuft…</translation>
    </message>
    <message>
        <source>Verification failed: %1</source>
        <translation>Verifikation fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Verification finished: some properties do not hold (see Problems)</source>
        <translation>Verifikation beendet: Einige Eigenschaften gelten nicht (siehe Probleme)</translation>
    </message>
    <message>
        <source>Verification finished: every property holds</source>
        <translation>Verifikation beendet: Alle Eigenschaften gelten</translation>
    </message>
    <message>
        <source>%1 counterexample</source>
        <translation>Gegenbeispiel %1</translation>
    </message>
    <message>
        <source>Replay in Simulator</source>
        <translation>Im Simulator abspielen</translation>
    </message>
    <message>
        <source>Could not replay %1.</source>
        <translation>%1 konnte nicht abgespielt werden.</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>&amp;Beispiele</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>&amp;Anordnung zurücksetzen</translation>
    </message>
    <message>
        <source>Put the panels and the toolbar back where they were at the first start</source>
        <translation>Fenster und Werkzeugleiste dorthin zurücksetzen, wo sie beim ersten Start waren</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <source>Export PLCopen XML</source>
        <translation>PLCopen XML exportieren</translation>
    </message>
    <message>
        <source>Open Example</source>
        <translation>Beispiel öffnen</translation>
    </message>
    <message>
        <source>Could not open the example “%1”.</source>
        <translation>Das Beispiel „%1“ konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>Opened the example “%1” as an untitled copy: Save As keeps your changes</source>
        <translation>Beispiel „%1“ als unbenannte Kopie geöffnet: „Speichern unter“ behält Ihre Änderungen</translation>
    </message>
    <message>
        <source>&amp;Hide Selected Elements</source>
        <translation>Ausgewählte Elemente &amp;ausblenden</translation>
    </message>
    <message>
        <source>Hide the selected states and transitions: the machine does not need them</source>
        <translation>Die ausgewählten Zustände und Transitionen ausblenden: Die Maschine braucht sie nicht</translation>
    </message>
    <message>
        <source>Sho&amp;w Selected Elements</source>
        <translation>Ausgewählte Elemente &amp;einblenden</translation>
    </message>
    <message>
        <source>Show the selected hidden states and transitions again</source>
        <translation>Die ausgewählten ausgeblendeten Zustände und Transitionen wieder einblenden</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>How to build a model, simulate, verify and export, offline; F1 opens it at the part about the panel you are in</source>
        <translation>Wie man ein Modell erstellt, simuliert, verifiziert und exportiert, offline (auf Englisch); F1 öffnet es bei dem Teil über das Fenster, in dem Sie sind</translation>
    </message>
    <message>
        <source>Step &amp;Back</source>
        <translation>Zyklus zu&amp;rück</translation>
    </message>
    <message>
        <source>Show the previous scan of the run; a scan or Run from there continues from it and drops the later scans</source>
        <translation>Den vorherigen Zyklus des Laufs zeigen; ein Zyklus oder Ausführen von dort setzt bei ihm fort und verwirft die späteren Zyklen</translation>
    </message>
    <message>
        <source>Step &amp;Forward</source>
        <translation>Zyklus vor&amp;wärts</translation>
    </message>
    <message>
        <source>Show the next scan of the run&apos;s history</source>
        <translation>Den nächsten Zyklus im Verlauf des Laufs zeigen</translation>
    </message>
    <message>
        <source>Prove what the GEMMA layer and the nested GRAFCETs can and cannot do for every input sequence, and check your properties; the findings go to the Problems dock</source>
        <translation>Beweisen, was die GEMMA-Ebene und die eingebetteten GRAFCETs für jede Eingangsfolge tun können und was nicht, und Ihre Eigenschaften prüfen; die Befunde kommen in das Fenster Probleme</translation>
    </message>
    <message>
        <source>Verify with &amp;Exact Time</source>
        <translation>Mit e&amp;xakter Zeit verifizieren</translation>
    </message>
    <message>
        <source>Count time in scans when verifying: every timer elapses exactly when the PLC&apos;s would, instead of &quot;may or may not have elapsed&quot; (more states)</source>
        <translation>Beim Verifizieren die Zeit in Zyklen zählen: jeder Timer läuft genau dann ab, wenn der der SPS ablaufen würde, statt &quot;kann abgelaufen sein oder nicht&quot; (mehr Zustände)</translation>
    </message>
    <message>
        <source>%1 was opened, but not everything in the file was taken over.</source>
        <translation>%1 wurde geöffnet, aber nicht alles in der Datei wurde übernommen.</translation>
    </message>
    <message>
        <source>Verification finished: nothing is violated, but some properties are undecided (see Problems)</source>
        <translation>Verifikation beendet: nichts ist verletzt, aber einige Eigenschaften sind unentschieden (siehe Probleme)</translation>
    </message>
    <message>
        <source>&amp;Fit to Window</source>
        <translation>An &amp;Fenster anpassen</translation>
    </message>
    <message>
        <source>Put every command, unit mode, GRAFCET, variable and setting back to a new PackML model of this edition? You can undo this.</source>
        <translation>Alle Befehle, Betriebsarten, GRAFCETs, Variablen und Einstellungen auf ein neues PackML-Modell dieser Ausgabe zurücksetzen? Sie können das rückgängig machen.</translation>
    </message>
    <message>
        <source>Verify with the &amp;Machine</source>
        <translation>Mit der &amp;Maschine verifizieren</translation>
    </message>
    <message>
        <source>Explore the program with the model&apos;s machine: the sensors it drives follow the cylinders and conveyors instead of taking any value</source>
        <translation>Das Programm mit der Maschine des Modells erkunden: Die Sensoren, die sie setzt, folgen den Zylindern und Förderbändern, statt jeden Wert anzunehmen</translation>
    </message>
    <message>
        <source>Verification cancelled: the model, the Complete settings, the machine&apos;s use or Exact Time changed</source>
        <translation>Verifikation abgebrochen: Das Modell, die Complete-Einstellungen, die Verwendung der Maschine oder die exakte Zeit haben sich geändert</translation>
    </message>
    <message>
        <source>Co&amp;nnect…</source>
        <translation>&amp;Verbinden…</translation>
    </message>
    <message>
        <source>Link the simulation to a digital twin, a soft PLC or an HMI over Modbus TCP; it then runs in real time</source>
        <translation>Die Simulation über Modbus TCP mit einem digitalen Zwilling, einer Soft-SPS oder einem HMI verbinden; sie läuft dann in Echtzeit</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <source>End the Modbus TCP link</source>
        <translation>Die Modbus-TCP-Verbindung beenden</translation>
    </message>
    <message>
        <source>Verify with Single &amp;Faults</source>
        <translation>Mit einzelnen &amp;Fehlern verifizieren</translation>
    </message>
    <message>
        <source>With the machine, also explore any one fault from any scan on: a sensor stuck or flickering, a cylinder or conveyor jammed</source>
        <translation>Mit der Maschine zusätzlich jeden einzelnen Fehler ab jedem Zyklus untersuchen: ein Sensor, der hängt oder flackert, ein blockierter Zylinder oder Förderer</translation>
    </message>
    <message>
        <source>The Modbus link is for GEMMA models; PackML models are not linked yet</source>
        <translation>Die Modbus-Verbindung ist für GEMMA-Modelle; PackML-Modelle werden noch nicht verbunden</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>The Modbus link could not start: %1</source>
        <translation>Die Modbus-Verbindung konnte nicht starten: %1</translation>
    </message>
    <message>
        <source>Undo</source>
        <extracomment>the Undo button of the toolbar (the Edit menu names the command)</extracomment>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Redo</source>
        <extracomment>the Redo button of the toolbar (the Edit menu names the command)</extracomment>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Undo %1</source>
        <translation>Rückgängig: %1</translation>
    </message>
    <message>
        <source>Redo %1</source>
        <translation>Wiederholen: %1</translation>
    </message>
</context>
<context>
    <name>editor::ModbusConnectDialog</name>
    <message>
        <source>Coil</source>
        <translation>Spule</translation>
    </message>
    <message>
        <source>Discrete input</source>
        <translation>Diskreter Eingang</translation>
    </message>
    <message>
        <source>Holding register</source>
        <translation>Halteregister</translation>
    </message>
    <message>
        <source>Input register</source>
        <translation>Eingangsregister</translation>
    </message>
    <message>
        <source>Connect over Modbus TCP</source>
        <translation>Über Modbus TCP verbinden</translation>
    </message>
    <message>
        <source>Server: the twin connects to the simulator</source>
        <translation>Server: der Zwilling verbindet sich mit dem Simulator</translation>
    </message>
    <message>
        <source>Client: the simulator connects to the twin</source>
        <translation>Client: der Simulator verbindet sich mit dem Zwilling</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabelle</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Modus:</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <source>Unit id:</source>
        <translation>Unit-ID:</translation>
    </message>
    <message>
        <source>Load CSV…</source>
        <translation>CSV laden…</translation>
    </message>
    <message>
        <source>Save As CSV…</source>
        <translation>Als CSV speichern…</translation>
    </message>
    <message>
        <source>Default Map</source>
        <translation>Standardzuordnung</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Map (each table numbered from 0 in declaration order unless loaded):</source>
        <translation>Zuordnung (jede Tabelle ab 0 in Deklarationsreihenfolge nummeriert, sofern nicht geladen):</translation>
    </message>
    <message>
        <source>Load Modbus Map</source>
        <translation>Modbus-Zuordnung laden</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Save Modbus Map</source>
        <translation>Modbus-Zuordnung speichern</translation>
    </message>
    <message>
        <source>Line %1, column %2: %3</source>
        <translation>Zeile %1, Spalte %2: %3</translation>
    </message>
    <message>
        <source>%1 cannot be used:</source>
        <translation>%1 kann nicht verwendet werden:</translation>
    </message>
    <message>
        <source>%1 could not be saved: %2</source>
        <translation>%1 konnte nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>editor::ModbusConnection</name>
    <message>
        <source>The simulation could not start.</source>
        <translation>Die Simulation konnte nicht starten.</translation>
    </message>
    <message>
        <source>Modbus server on %1, unit %2, clients connected: %3</source>
        <translation>Modbus-Server auf %1, Unit %2, verbundene Clients: %3</translation>
    </message>
    <message>
        <source>Modbus client of %1: connected</source>
        <translation>Modbus-Client von %1: verbunden</translation>
    </message>
    <message>
        <source>Modbus client of %1: connecting</source>
        <translation>Modbus-Client von %1: verbindet</translation>
    </message>
    <message>
        <source>Modbus client of %1: not connected, trying again</source>
        <translation>Modbus-Client von %1: nicht verbunden, neuer Versuch</translation>
    </message>
    <message>
        <source>Set by the twin: %1</source>
        <translation>Vom Zwilling gesetzt: %1</translation>
    </message>
    <message>
        <source>Errors: %1, the last: %2</source>
        <translation>Fehler: %1, der letzte: %2</translation>
    </message>
</context>
<context>
    <name>editor::ModelCommand</name>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 is the edit (&quot;Rename variable Stop to Halt&quot;), %2 why the model refused it</extracomment>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>editor::ModelSettingsDialog</name>
    <message>
        <source>Model Settings</source>
        <translation>Modelleinstellungen</translation>
    </message>
    <message>
        <source>The project name written into the exported PLCopen XML</source>
        <translation>Der Projektname, der in das exportierte PLCopen XML geschrieben wird</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>The period of the cyclic PLC task that runs GEMMA</source>
        <translation>Die Periode der zyklischen SPS-Task, die GEMMA ausführt</translation>
    </message>
    <message>
        <source>The flavour of the generated Structured Text and its preview</source>
        <translation>Die Variante des generierten Strukturierten Texts und seiner Vorschau</translation>
    </message>
    <message>
        <source>Use the cycle time and dialect for &amp;new models</source>
        <translation>Zykluszeit und Dialekt für neue &amp;Modelle verwenden</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>PLC &amp;cycle time:</source>
        <translation>SPS-&amp;Zykluszeit:</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialekt:</translation>
    </message>
    <message>
        <source>Change model settings</source>
        <translation>Modelleinstellungen ändern</translation>
    </message>
    <message>
        <source>One evolution per scan</source>
        <translation>Eine Entwicklung pro Zyklus</translation>
    </message>
    <message>
        <source>Until stable</source>
        <translation>Bis stabil</translation>
    </message>
    <message>
        <source>How a nested GRAFCET evolves in one call of its function block</source>
        <translation>Wie sich ein eingebetteter GRAFCET in einem Aufruf seines Funktionsbausteins entwickelt</translation>
    </message>
    <message>
        <source>&amp;Evolution rule:</source>
        <translation>&amp;Entwicklungsregel:</translation>
    </message>
    <message>
        <source>Each scan repeats evolutions until no transition can fire (IEC 60848&apos;s search for stability), at most one more than the GRAFCET has transitions; if the last one still fires, the function block reports Unstable.</source>
        <translation>Jeder Zyklus wiederholt Entwicklungen, bis keine Transition mehr schalten kann (die Suche nach Stabilität der IEC 60848), höchstens eine mehr, als der GRAFCET Transitionen hat; schaltet die letzte noch, meldet der Funktionsbaustein Unstable.</translation>
    </message>
    <message>
        <source>Each scan fires the transitions enabled at its start once, as SFC runtimes such as CODESYS do.</source>
        <translation>Jeder Zyklus schaltet die zu seinem Beginn freigegebenen Transitionen einmal, wie SFC-Laufzeitsysteme wie CODESYS.</translation>
    </message>
    <message>
        <source>PackML</source>
        <translation>PackML</translation>
    </message>
</context>
<context>
    <name>editor::NewModelDialog</name>
    <message>
        <source>GEMMA</source>
        <translation>GEMMA</translation>
    </message>
    <message>
        <source>The GEMMA chart (stop, operation and failure procedures) with a nested GRAFCET in each macro-step: the GEMMA-GRAFCET method.</source>
        <translation>Das GEMMA-Diagramm (Stopp-, Betriebs- und Fehlerverfahren) mit einem verschachtelten GRAFCET in jedem Makroschritt: die GEMMA-GRAFCET-Methode.</translation>
    </message>
    <message>
        <source>PackML, 2015 edition</source>
        <translation>PackML, Ausgabe 2015</translation>
    </message>
    <message>
        <source>The ISA-TR88.00.02-2015 state machine with unit modes: Production, Maintenance and Manual, a GRAFCET in each acting state.</source>
        <translation>Der Zustandsautomat nach ISA-TR88.00.02-2015 mit Betriebsarten: Production, Maintenance und Manual, ein GRAFCET in jedem aktiven Zustand.</translation>
    </message>
    <message>
        <source>PackML, 2022 edition</source>
        <translation>PackML, Ausgabe 2022</translation>
    </message>
    <message>
        <source>The ISA-TR88.00.02-2022 state machine: as 2015, with the Complete command that ends Execute.</source>
        <translation>Der Zustandsautomat nach ISA-TR88.00.02-2022: wie 2015, mit dem Befehl Complete, der Execute beendet.</translation>
    </message>
    <message>
        <source>New Model</source>
        <translation>Neues Modell</translation>
    </message>
    <message>
        <source>Which chart does the new model fill in?</source>
        <translation>Welches Diagramm füllt das neue Modell aus?</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartContextMenu</name>
    <message>
        <source>&amp;Open GRAFCET</source>
        <translation>GRAFCET ö&amp;ffnen</translation>
    </message>
    <message>
        <source>&amp;Choose Its GRAFCET…</source>
        <translation>Sein GRAFCET &amp;wählen…</translation>
    </message>
    <message>
        <source>Its own GRAFCET in this mode, the one of another mode, or none</source>
        <translation>Ein eigenes GRAFCET in dieser Betriebsart, das einer anderen Betriebsart oder keines</translation>
    </message>
    <message>
        <source>Edit the %1 &amp;Condition…</source>
        <translation>&amp;Bedingung von %1 bearbeiten…</translation>
    </message>
    <message>
        <source>Show in &amp;Mode</source>
        <translation>In Betriebs&amp;art zeigen</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartTexts</name>
    <message>
        <source>Disabled in mode %1: never active there.</source>
        <extracomment>%1: the unit mode the chart shows (&quot;3 Manual&quot;)</extracomment>
        <translation>Im Modus %1 deaktiviert: dort nie aktiv.</translation>
    </message>
    <message>
        <source>Runs its own nested GRAFCET in this mode.</source>
        <translation>Führt in diesem Modus sein eigenes eingebettetes GRAFCET aus.</translation>
    </message>
    <message>
        <source>Runs the nested GRAFCET of mode %1 for this state.</source>
        <extracomment>%1: the number of the unit mode whose GRAFCET runs</extracomment>
        <translation>Führt das eingebettete GRAFCET von Modus %1 für diesen Zustand aus.</translation>
    </message>
    <message>
        <source>No nested GRAFCET in this mode: it waits for a command.</source>
        <translation>Kein eingebettetes GRAFCET in diesem Modus: wartet auf einen Befehl.</translation>
    </message>
    <message>
        <source>No nested GRAFCET in this mode: it completes at once.</source>
        <translation>Kein eingebettetes GRAFCET in diesem Modus: ist sofort abgeschlossen.</translation>
    </message>
    <message>
        <source>SC (State Complete): %1 has done its work.</source>
        <extracomment>%1: a PackML state (&quot;Starting&quot;)</extracomment>
        <translation>SC (State Complete): %1 hat seine Arbeit getan.</translation>
    </message>
    <message>
        <source>Optional: exists only under an option of Model Settings.</source>
        <translation>Optional: nur mit einer Option der Modelleinstellungen vorhanden.</translation>
    </message>
    <message>
        <source>In mode %1, %2 is disabled: this transition leads to %3.</source>
        <extracomment>%1: the unit mode (&quot;3 Manual&quot;), %2: the disabled state, %3: where the transition leads instead</extracomment>
        <translation>Im Modus %1 ist %2 deaktiviert: dieser Übergang führt nach %3.</translation>
    </message>
    <message>
        <source>Accepted by every state in the Abort frame, before their own transitions.</source>
        <translation>Von jedem Zustand im Abort-Rahmen angenommen, vor dessen eigenen Übergängen.</translation>
    </message>
    <message>
        <source>Accepted by every state in the Stop frame, before their own transitions.</source>
        <translation>Von jedem Zustand im Stop-Rahmen angenommen, vor dessen eigenen Übergängen.</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Bedingung:</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartView</name>
    <message>
        <source>Unit &amp;mode:</source>
        <translation>Betriebs&amp;modus:</translation>
    </message>
    <message>
        <source>The unit mode the chart shows: its disabled states greyed, its skipped transitions labelled with where they lead</source>
        <translation>Der Betriebsmodus, den das Diagramm zeigt: seine deaktivierten Zustände grau, übersprungene Übergänge mit ihrem Ziel beschriftet</translation>
    </message>
</context>
<context>
    <name>editor::PackmlCommandsDock</name>
    <message>
        <source>Commands</source>
        <translation>Befehle</translation>
    </message>
    <message>
        <source>Commands belong to PackML models: this model follows GEMMA.</source>
        <translation>Befehle gehören zu PackML-Modellen: Dieses Modell folgt GEMMA.</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>a PackML command&apos;s row: its PackTags number and name, &quot;4 Hold&quot;</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Bedingung:</translation>
    </message>
    <message>
        <source>e.g. %1, or FALSE for a command given only through CntrlCmd</source>
        <translation>z. B. %1, oder FALSE für einen Befehl, der nur über CntrlCmd kommt</translation>
    </message>
    <message>
        <source>Issues the command at its rising edge. Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND, XOR, OR, comparisons.
Ctrl+Space completes a variable name.</source>
        <translation>Gibt den Befehl bei seiner steigenden Flanke. Strukturierter Text: deklarierte Variablen, Zahlen, TRUE, FALSE, NOT, AND, XOR, OR, Vergleiche.
Strg+Leertaste vervollständigt einen Variablennamen.</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Kommentar:</translation>
    </message>
    <message>
        <source>Where the command comes from on this machine</source>
        <translation>Woher der Befehl an dieser Maschine kommt</translation>
    </message>
</context>
<context>
    <name>editor::PackmlModeForm</name>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>User modes (4 to 31) take an IEC identifier that no other mode has and the generated code does not use; it becomes part of function block names.
Modes 1 to 3 are Production, Maintenance and Manual.</source>
        <translation>Benutzerbetriebsarten (4 bis 31) tragen einen IEC-Bezeichner, den keine andere Betriebsart hat und der generierte Code nicht verwendet; er wird Teil von Funktionsbausteinnamen.
Die Betriebsarten 1 bis 3 sind Production, Maintenance und Manual.</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Kommentar:</translation>
    </message>
    <message>
        <source>What the unit does in this mode</source>
        <translation>Was die Einheit in dieser Betriebsart tut</translation>
    </message>
    <message>
        <source>Request condition:</source>
        <translation>Anforderungsbedingung:</translation>
    </message>
    <message>
        <source>None: requested through UnitMode only (e.g. KeyManual)</source>
        <translation>Keine: nur über UnitMode angefordert (z. B. KeyManual)</translation>
    </message>
    <message>
        <source>Requests this mode at its rising edge, as a rising edge of UnitModeChangeRequest with UnitMode set to its number does.</source>
        <translation>Fordert diese Betriebsart bei ihrer steigenden Flanke an, wie es eine steigende Flanke von UnitModeChangeRequest mit UnitMode auf ihrer Nummer tut.</translation>
    </message>
    <message>
        <source>Disabled states</source>
        <translation>Deaktivierte Zustände</translation>
    </message>
    <message>
        <source>Stopped, Idle, Execute and Aborted are never disabled. Disabling Held, Suspended or Complete disables the acting states of its loop; enabling one of those enables it again.</source>
        <translation>Stopped, Idle, Execute und Aborted werden nie deaktiviert. Das Deaktivieren von Held, Suspended oder Complete deaktiviert die aktiven Zustände seiner Schleife; das Aktivieren eines davon aktiviert ihn wieder.</translation>
    </message>
    <message>
        <source>Mode change allowed in</source>
        <translation>Betriebsartwechsel erlaubt in</translation>
    </message>
    <message>
        <source>A change to or from this mode is granted in a state that both modes list and the requested mode enables.</source>
        <translation>Ein Wechsel in diese oder aus dieser Betriebsart wird in einem Zustand gewährt, den beide Betriebsarten auflisten und die angeforderte aktiviert.</translation>
    </message>
    <message>
        <source>%1 is disabled in this mode: no change can be granted there.</source>
        <translation>%1 ist in dieser Betriebsart deaktiviert: Dort kann kein Wechsel gewährt werden.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlModesDock</name>
    <message>
        <source>Modes</source>
        <translation>Betriebsarten</translation>
    </message>
    <message>
        <source>Unit modes belong to PackML models: this model follows GEMMA.</source>
        <translation>Betriebsarten gehören zu PackML-Modellen: Dieses Modell folgt GEMMA.</translation>
    </message>
    <message>
        <source>The number of the next user mode (PackTags UnitMode)</source>
        <translation>Die Nummer der nächsten Benutzerbetriebsart (PackTags UnitMode)</translation>
    </message>
    <message>
        <source>&amp;Add Mode</source>
        <translation>Betriebsart &amp;hinzufügen</translation>
    </message>
    <message>
        <source>Adds a user mode with this number: every state enabled, mode changes in Stopped, Idle and Aborted</source>
        <translation>Fügt eine Benutzerbetriebsart mit dieser Nummer hinzu: alle Zustände aktiv, Betriebsartwechsel in Stopped, Idle und Aborted</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <source>&amp;Initial mode:</source>
        <translation>&amp;Anfangsbetriebsart:</translation>
    </message>
    <message>
        <source>The mode the unit is in at power-up</source>
        <translation>Die Betriebsart der Einheit beim Einschalten</translation>
    </message>
    <message>
        <source>Production is the mode every unit has</source>
        <translation>Production ist die Betriebsart, die jede Einheit hat</translation>
    </message>
    <message>
        <source>Removes the mode with its GRAFCETs</source>
        <translation>Entfernt die Betriebsart mit ihren GRAFCETs</translation>
    </message>
</context>
<context>
    <name>editor::PackmlSettingsWidget</name>
    <message>
        <source>&amp;Hold accepted in Suspended</source>
        <translation>&amp;Hold in Suspended angenommen</translation>
    </message>
    <message>
        <source>Suspended → Holding on Hold, an optional transition of the 2015 model and a standard one of 2022</source>
        <translation>Suspended → Holding bei Hold, ein optionaler Übergang des Modells 2015 und ein Standardübergang von 2022</translation>
    </message>
    <message>
        <source>C&amp;omplete accepted in Suspended and Held</source>
        <translation>C&amp;omplete in Suspended und Held angenommen</translation>
    </message>
    <message>
        <source>Suspended and Held → Completing on the Complete command (2022 edition only)</source>
        <translation>Suspended und Held → Completing beim Befehl Complete (nur Ausgabe 2022)</translation>
    </message>
    <message>
        <source>The state at power-up: Stopped as usual, Aborted for a unit that must be cleared after a power loss, Idle for one with nothing to reset</source>
        <translation>Der Zustand beim Einschalten: Stopped üblicherweise, Aborted für eine Einheit, die nach einem Stromausfall quittiert werden muss, Idle für eine ohne Rücksetzbedarf</translation>
    </message>
    <message>
        <source>PackML &amp;edition:</source>
        <translation>PackML-&amp;Ausgabe:</translation>
    </message>
    <message>
        <source>Initial &amp;state:</source>
        <translation>Anfangs&amp;zustand:</translation>
    </message>
    <message>
        <source>2022: Execute is left on the Complete command, which a new model conditions on Cmd_Complete; its State Complete leads nowhere.</source>
        <translation>2022: Execute wird mit dem Befehl Complete verlassen, den ein neues Modell an Cmd_Complete bindet; sein State Complete führt nirgendwohin.</translation>
    </message>
    <message>
        <source>2015: Execute&apos;s State Complete leads to Completing; there is no Complete command.</source>
        <translation>2015: Der State Complete von Execute führt zu Completing; es gibt keinen Befehl Complete.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlSimulationDock</name>
    <message>
        <source>PackML Simulation</source>
        <translation>PackML-Simulation</translation>
    </message>
    <message>
        <source>Start Simulation</source>
        <translation>Simulation starten</translation>
    </message>
    <message>
        <source>Run or pause the scans</source>
        <translation>Zyklen ausführen oder anhalten</translation>
    </message>
    <message>
        <source>Single scan</source>
        <translation>Einzelzyklus</translation>
    </message>
    <message>
        <source>Step back: show the scan before</source>
        <translation>Zurück: den vorigen Zyklus zeigen</translation>
    </message>
    <message>
        <source>Step forward: show the scan after</source>
        <translation>Vor: den nächsten Zyklus zeigen</translation>
    </message>
    <message>
        <source>Reset: the initial state and mode, inputs at their defaults</source>
        <translation>Zurücksetzen: Anfangszustand und -betriebsart, Eingänge auf ihren Vorgabewerten</translation>
    </message>
    <message>
        <source>End the simulation</source>
        <translation>Simulation beenden</translation>
    </message>
    <message>
        <source>Scans/s:</source>
        <translation>Zyklen/s:</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>Ablauf</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Szenario</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Befehle</translation>
    </message>
    <message>
        <source>Unit mode</source>
        <translation>Betriebsart der Einheit</translation>
    </message>
    <message>
        <source>Pick a mode to request it: the mode manager grants it or says why not</source>
        <translation>Eine Betriebsart wählen, um sie anzufordern: die Betriebsartenverwaltung gewährt sie oder sagt, warum nicht</translation>
    </message>
    <message>
        <source>Function block</source>
        <translation>Funktionsbaustein</translation>
    </message>
    <message>
        <source>SC from the skeleton</source>
        <extracomment>the State Complete of a state without nested GRAFCET: as the generated skeleton sets it</extracomment>
        <translation>SC aus dem Gerüst</translation>
    </message>
    <message>
        <source>SC = TRUE (by hand)</source>
        <translation>SC = TRUE (von Hand)</translation>
    </message>
    <message>
        <source>SC = FALSE (by hand)</source>
        <translation>SC = FALSE (von Hand)</translation>
    </message>
    <message>
        <source>The State Complete of a state without nested GRAFCET, set by hand to hold an acting state or to complete Execute</source>
        <translation>Das State Complete eines Zustands ohne eingebettetes GRAFCET, von Hand gesetzt, um einen aktiven Zustand festzuhalten oder Execute abzuschließen</translation>
    </message>
    <message>
        <source>Replay Scenario…</source>
        <translation>Szenario abspielen…</translation>
    </message>
    <message>
        <source>Start the simulation to play the unit&apos;s commands and modes.</source>
        <translation>Starten Sie die Simulation, um die Befehle und Betriebsarten der Einheit zu spielen.</translation>
    </message>
    <message>
        <source>Scan %1: %2 in %3</source>
        <extracomment>%1: a scan number, %2: a PackML state (Execute), %3: a unit mode (Production)</extracomment>
        <translation>Zyklus %1: %2 in %3</translation>
    </message>
    <message>
        <source>%1 (history; the latest scan is %2)</source>
        <extracomment>%1: a status, %2: the latest scan</extracomment>
        <translation>%1 (Verlauf; der letzte Zyklus ist %2)</translation>
    </message>
    <message>
        <source>%1 is accepted in %2</source>
        <translation>%1 wird in %2 angenommen</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2: pressing it shows why</source>
        <translation>%1 wird in %2 nicht angenommen: ein Druck zeigt, warum</translation>
    </message>
    <message>
        <source>%1: requested, read by the next scan</source>
        <translation>%1: angefordert, wird im nächsten Zyklus gelesen</translation>
    </message>
    <message>
        <source>%1 is a wait state: no function block runs in it</source>
        <translation>%1 ist ein Wartezustand: in ihm läuft kein Funktionsbaustein</translation>
    </message>
    <message>
        <source>%1: active steps %2, Complete = %3</source>
        <extracomment>%1: a function block instance (Production_Execute), %2: step numbers, %3: TRUE or FALSE</extracomment>
        <translation>%1: aktive Schritte %2, Complete = %3</translation>
    </message>
    <message>
        <source>%1 runs no GRAFCET: Complete = %2</source>
        <translation>%1 führt kein GRAFCET aus: Complete = %2</translation>
    </message>
    <message>
        <source>Replaying %1: scan %2 of %3</source>
        <extracomment>%1: a scenario file, %2: the scan shown, %3: its last scan</extracomment>
        <translation>%1 wird abgespielt: Zyklus %2 von %3</translation>
    </message>
    <message>
        <source>%1 passed: all %2 expectation(s) met</source>
        <translation>%1 bestanden: alle %2 Erwartung(en) erfüllt</translation>
    </message>
    <message>
        <source>%1 failed: %2 of %3 expectation(s) did not hold</source>
        <translation>%1 fehlgeschlagen: %2 von %3 Erwartung(en) nicht erfüllt</translation>
    </message>
    <message>
        <source>Cannot replay %1:
%2</source>
        <translation>%1 kann nicht abgespielt werden:
%2</translation>
    </message>
    <message>
        <source>Replay Scenario</source>
        <translation>Szenario abspielen</translation>
    </message>
    <message>
        <source>Scenarios (*.scenario *.txt);;All files (*)</source>
        <translation>Szenarien (*.scenario *.txt);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>editor::PackmlStateDock</name>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Select a state in the PackML chart to see what it means and what runs in it.</source>
        <translation>Wählen Sie einen Zustand im PackML-Diagramm, um zu sehen, was er bedeutet und was darin läuft.</translation>
    </message>
    <message>
        <source>Nested GRAFCET per mode</source>
        <translation>Eingebetteter GRAFCET je Betriebsart</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>a PackML state&apos;s title: its PackTags number and name, &quot;6 Execute&quot;</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Own: a nested GRAFCET for this mode; Same as: the one of another mode; None: the state&apos;s skeleton (%1).</source>
        <translation>Eigener: ein eingebetteter GRAFCET für diese Betriebsart; Wie: der einer anderen Betriebsart; Keiner: das Gerüst des Zustands (%1).</translation>
    </message>
    <message>
        <source>Execute waits for a command</source>
        <translation>Execute wartet auf einen Befehl</translation>
    </message>
    <message>
        <source>the state completes at once</source>
        <translation>der Zustand ist sofort abgeschlossen</translation>
    </message>
    <message>
        <source>A wait state runs no GRAFCET.</source>
        <translation>Ein Wartezustand führt keinen GRAFCET aus.</translation>
    </message>
    <message>
        <source>Open GRAFCET</source>
        <translation>GRAFCET öffnen</translation>
    </message>
    <message>
        <source>None (skeleton)</source>
        <translation>Keiner (Gerüst)</translation>
    </message>
    <message>
        <source>Own GRAFCET</source>
        <translation>Eigener GRAFCET</translation>
    </message>
    <message>
        <source>Same as %1</source>
        <translation>Wie %1</translation>
    </message>
    <message>
        <source>Same as mode %1 (no GRAFCET there)</source>
        <translation>Wie Betriebsart %1 (dort kein GRAFCET)</translation>
    </message>
    <message>
        <source>%1 is disabled in this mode: nothing runs there.</source>
        <translation>%1 ist in dieser Betriebsart deaktiviert: Dort läuft nichts.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlTraceModel</name>
    <message>
        <source>mode %1 → %2</source>
        <extracomment>a unit mode change in one scan: from, to</extracomment>
        <translation>Betriebsart %1 → %2</translation>
    </message>
    <message>
        <source>Execute resumed</source>
        <translation>Execute fortgesetzt</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Zyklus</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Betriebsart</translation>
    </message>
    <message>
        <source>Fired</source>
        <translation>Geschaltet</translation>
    </message>
    <message>
        <source>Dropped</source>
        <translation>Verworfen</translation>
    </message>
</context>
<context>
    <name>editor::PackmlVariablesPanel</name>
    <message>
        <source>Inputs</source>
        <translation>Eingänge</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Ausgänge</translation>
    </message>
</context>
<context>
    <name>editor::ProblemCounter</name>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n Fehler</numerusform>
            <numerusform>%n Fehler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <source>Show the Problems panel</source>
        <translation>Den Bereich „Probleme“ anzeigen</translation>
    </message>
    <message>
        <source>No problems</source>
        <translation>Keine Probleme</translation>
    </message>
    <message numerus="yes">
        <source>Verification (outdated): %n finding(s)</source>
        <extracomment>the verification&apos;s findings after the checks&apos; problems in the status bar</extracomment>
        <translation>
            <numerusform>Verifikation (veraltet): %n Befund</numerusform>
            <numerusform>Verifikation (veraltet): %n Befunde</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Verification: %n finding(s)</source>
        <translation>
            <numerusform>Verifikation: %n Befund</numerusform>
            <numerusform>Verifikation: %n Befunde</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::ProblemsDock</name>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Probleme</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Element</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>1 Fehler</translation>
    </message>
    <message numerus="yes">
        <source>%n errors</source>
        <translation>
            <numerusform>%n Fehler</numerusform>
            <numerusform>%n Fehler</numerusform>
        </translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 Warnung</translation>
    </message>
    <message numerus="yes">
        <source>%n warnings</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
    <message>
        <source>1 info</source>
        <translation>1 Info</translation>
    </message>
    <message numerus="yes">
        <source>%n infos</source>
        <translation>
            <numerusform>%n Info</numerusform>
            <numerusform>%n Infos</numerusform>
        </translation>
    </message>
    <message>
        <source>Show or hide the errors</source>
        <translation>Fehler ein- oder ausblenden</translation>
    </message>
    <message>
        <source>Show or hide the warnings</source>
        <translation>Warnungen ein- oder ausblenden</translation>
    </message>
    <message>
        <source>Show or hide the information messages</source>
        <translation>Informationsmeldungen ein- oder ausblenden</translation>
    </message>
    <message>
        <source>Checks (%1)</source>
        <translation>Prüfungen (%1)</translation>
    </message>
    <message>
        <source>Verification</source>
        <translation>Verifikation</translation>
    </message>
    <message>
        <source>Verification (outdated)</source>
        <translation>Verifikation (veraltet)</translation>
    </message>
    <message>
        <source>Verification (%1)</source>
        <translation>Verifikation (%1)</translation>
    </message>
    <message>
        <source>%1 step %2</source>
        <extracomment>A step of the nested GRAFCET of a GEMMA step: &quot;F1 step 3&quot;</extracomment>
        <translation>%1 Schritt %2</translation>
    </message>
    <message>
        <source>%1 T%2</source>
        <extracomment>A transition of the nested GRAFCET of a GEMMA step: &quot;F1 T2&quot;</extracomment>
        <translation>%1 T%2</translation>
    </message>
    <message>
        <source>%1 GRAFCET</source>
        <extracomment>The row that holds the problems of a GEMMA step&apos;s nested GRAFCET: &quot;F1 GRAFCET&quot;</extracomment>
        <translation>GRAFCET von %1</translation>
    </message>
    <message>
        <source>Nested GRAFCET of %1: 1 problem</source>
        <translation>Eingebetteter GRAFCET von %1: 1 Problem</translation>
    </message>
    <message numerus="yes">
        <source>Nested GRAFCET of %1: %n problems</source>
        <translation>
            <numerusform>Eingebetteter GRAFCET von %1: %n Problem</numerusform>
            <numerusform>Eingebetteter GRAFCET von %1: %n Probleme</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>machine component %1</source>
        <extracomment>A component of the virtual machine: &quot;machine component Clamp&quot;</extracomment>
        <translation>Maschinenkomponente %1</translation>
    </message>
</context>
<context>
    <name>editor::PropertiesPanel</name>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Add Property</source>
        <translation>Eigenschaft hinzufügen</translation>
    </message>
    <message>
        <source>Add a property after the current one (Insert)</source>
        <translation>Eine Eigenschaft nach der aktuellen hinzufügen (Einfg)</translation>
    </message>
    <message>
        <source>Remove Property</source>
        <translation>Eigenschaft entfernen</translation>
    </message>
    <message>
        <source>Remove the current property (Delete)</source>
        <translation>Die aktuelle Eigenschaft entfernen (Entf)</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <source>&amp;Property:</source>
        <translation>&amp;Eigenschaft:</translation>
    </message>
    <message>
        <source>never A_Plus AND A_Minus</source>
        <translation>never A_Plus AND A_Minus</translation>
    </message>
    <message>
        <source>Write never P or always P, where P is a condition over the variables that may also use in S (the GEMMA step S is active), S.Xn (step n of S&apos;s nested GRAFCET is active) and a -&gt; b (if a then b). Verify (F7) proves or refutes each one.</source>
        <translation>Schreiben Sie never P oder always P, wobei P eine Bedingung über die Variablen ist, die auch in S (der GEMMA-Schritt S ist aktiv), S.Xn (Schritt n des eingebetteten GRAFCET von S ist aktiv) und a -&gt; b (wenn a, dann b) verwenden darf. Verifizieren (F7) beweist oder widerlegt jede.</translation>
    </message>
</context>
<context>
    <name>editor::PropertiesTableModel</name>
    <message>
        <source>Property</source>
        <translation>Eigenschaft</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Kommentar</translation>
    </message>
</context>
<context>
    <name>editor::RecentFiles</name>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>Liste &amp;leeren</translation>
    </message>
</context>
<context>
    <name>editor::SimulationDock</name>
    <message>
        <source>fires in the next scan</source>
        <translation>schaltet im nächsten Zyklus</translation>
    </message>
    <message>
        <source>condition FALSE</source>
        <translation>Bedingung FALSE</translation>
    </message>
    <message>
        <source>waits for Complete</source>
        <translation>wartet auf Complete</translation>
    </message>
    <message>
        <source>preempted by %1</source>
        <translation>verdrängt durch %1</translation>
    </message>
    <message>
        <source>condition unusable (always FALSE)</source>
        <translation>Bedingung unbrauchbar (immer FALSE)</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>The simulation runs the model scan by scan, as the generated program runs on the PLC: play the inputs, watch the active step and see why each transition fires or not. Editing is locked while it runs.</source>
        <translation>Die Simulation führt das Modell Zyklus für Zyklus aus, so wie das erzeugte Programm auf der SPS läuft: Eingänge bedienen, den aktiven Schritt verfolgen und sehen, warum jede Transition schaltet oder nicht. Während der Simulation ist das Bearbeiten gesperrt.</translation>
    </message>
    <message>
        <source>Start Simulation</source>
        <translation>Simulation starten</translation>
    </message>
    <message>
        <source>Explanation</source>
        <translation>Erklärung</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Szenario</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <source>Run scans at the chosen speed; press again to pause</source>
        <translation>Zyklen mit der gewählten Geschwindigkeit ausführen; erneut drücken zum Anhalten</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Zyklus</translation>
    </message>
    <message>
        <source>Run a single scan</source>
        <translation>Einen einzelnen Zyklus ausführen</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Back to the initial step, the inputs to their defaults; clears the trace</source>
        <translation>Zurück zum Anfangsschritt, Eingänge auf ihre Anfangswerte; löscht den Verlauf</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>End the simulation and unlock editing</source>
        <translation>Die Simulation beenden und das Bearbeiten freigeben</translation>
    </message>
    <message>
        <source>&amp;Speed:</source>
        <translation>&amp;Geschwindigkeit:</translation>
    </message>
    <message>
        <source> scans/s</source>
        <translation> Zyklen/s</translation>
    </message>
    <message>
        <source>Scans per second (the model&apos;s cycle time only sets the simulated time)</source>
        <translation>Zyklen pro Sekunde (die Zykluszeit des Modells bestimmt nur die simulierte Zeit)</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transition</translation>
    </message>
    <message>
        <source>Next scan</source>
        <translation>Nächster Zyklus</translation>
    </message>
    <message>
        <source>&amp;Record as Scenario…</source>
        <translation>Als Szenario &amp;aufzeichnen…</translation>
    </message>
    <message>
        <source>Re&amp;play Scenario…</source>
        <translation>Szenario ab&amp;spielen…</translation>
    </message>
    <message>
        <source>Run a scenario file from the initial step and check its expectations</source>
        <translation>Eine Szenariodatei ab dem Anfangsschritt ausführen und ihre Erwartungen prüfen</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Eingänge</translation>
    </message>
    <message>
        <source>The model declares no variables.</source>
        <translation>Das Modell deklariert keine Variablen.</translation>
    </message>
    <message>
        <source>Complete of nested steps</source>
        <translation>Complete der Schritte mit untergeordnetem Ablauf</translation>
    </message>
    <message>
        <source>Automatic: the skeleton function block completes at once. Manual: you play the nested behaviour and set Complete yourself.</source>
        <translation>Automatisch: Der Gerüst-Funktionsbaustein ist sofort abgeschlossen. Manuell: Sie spielen den untergeordneten Ablauf und setzen Complete selbst.</translation>
    </message>
    <message>
        <source>Switch %1 between TRUE and FALSE</source>
        <translation>%1 zwischen TRUE und FALSE umschalten</translation>
    </message>
    <message>
        <source>Press</source>
        <translation>Drücken</translation>
    </message>
    <message>
        <source>TRUE while held down, like a push button (for at least one scan)</source>
        <translation>TRUE, solange gedrückt, wie ein Taster (mindestens einen Zyklus lang)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>Manuell</translation>
    </message>
    <message>
        <source>How %1&apos;s function block sets Complete</source>
        <translation>Wie der Funktionsbaustein von %1 Complete setzt</translation>
    </message>
    <message>
        <source>Complete</source>
        <translation>Complete</translation>
    </message>
    <message>
        <source>The value the nested behaviour gives Complete (manual mode)</source>
        <translation>Der Wert, den der untergeordnete Ablauf Complete gibt (manueller Modus)</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Scan %1 · %2 s</source>
        <translation>Zyklus %1 · %2 s</translation>
    </message>
    <message>
        <source>%1.Complete = %2 (after the last call of its function block)</source>
        <translation>%1.Complete = %2 (nach dem letzten Aufruf seines Funktionsbausteins)</translation>
    </message>
    <message>
        <source>No visible step is active (State = %1).</source>
        <translation>Kein sichtbarer Schritt ist aktiv (State = %1).</translation>
    </message>
    <message>
        <source>Active step: &lt;b&gt;%1&lt;/b&gt; %2 · Entry = %3</source>
        <translation>Aktiver Schritt: &lt;b&gt;%1&lt;/b&gt; %2 · Entry = %3</translation>
    </message>
    <message>
        <source>%1 (family)</source>
        <translation>%1 (Familie)</translation>
    </message>
    <message>
        <source>The active step has no transition to evaluate.</source>
        <translation>Der aktive Schritt hat keine Transition auszuwerten.</translation>
    </message>
    <message>
        <source>Record this session as a scenario file, or replay one.</source>
        <translation>Diese Sitzung als Szenariodatei aufzeichnen oder eine abspielen.</translation>
    </message>
    <message>
        <source>%1: every expectation met (%2).</source>
        <translation>%1: alle Erwartungen erfüllt (%2).</translation>
    </message>
    <message>
        <source>%1: %2 of %3 expectations failed.</source>
        <translation>%1: %2 von %3 Erwartungen nicht erfüllt.</translation>
    </message>
    <message>
        <source>Line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>session</source>
        <translation>Sitzung</translation>
    </message>
    <message>
        <source>Record as Scenario</source>
        <translation>Als Szenario aufzeichnen</translation>
    </message>
    <message>
        <source>Simulation scenarios (*.scenario *.txt);;All files (*)</source>
        <translation>Simulationsszenarien (*.scenario *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>%1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Recorded %1 scans to %2.</source>
        <translation>%1 Zyklen in %2 aufgezeichnet.</translation>
    </message>
    <message>
        <source>Replay Scenario</source>
        <translation>Szenario abspielen</translation>
    </message>
    <message>
        <source>Could not replay %1.</source>
        <translation>%1 konnte nicht abgespielt werden.</translation>
    </message>
    <message>
        <source>upstream step not active</source>
        <translation>vorausgehender Schritt nicht aktiv</translation>
    </message>
    <message>
        <source>receptivity FALSE</source>
        <translation>Weiterschaltbedingung FALSE</translation>
    </message>
    <message>
        <source>receptivity unusable (always FALSE)</source>
        <translation>Weiterschaltbedingung unbrauchbar (immer FALSE)</translation>
    </message>
    <message>
        <source>not called</source>
        <translation>nicht aufgerufen</translation>
    </message>
    <message>
        <source>Save this session since the last reset as a scenario file: the inputs of each scan, and expectations for every transition that fired, every output that changed and every nested situation that changed</source>
        <translation>Diese Sitzung seit dem letzten Zurücksetzen als Szenariodatei speichern: die Eingänge jedes Zyklus und Erwartungen für jede geschaltete Transition, jeden geänderten Ausgang und jede geänderte Situation eines eingebetteten GRAFCETs</translation>
    </message>
    <message>
        <source>GRAFCET of %1: no step active</source>
        <translation>GRAFCET von %1: kein Schritt aktiv</translation>
    </message>
    <message>
        <source>GRAFCET of %1: steps %2</source>
        <translation>GRAFCET von %1: Schritte %2</translation>
    </message>
    <message>
        <source>initialised again in the next scan (steps %1)</source>
        <translation>wird im nächsten Zyklus neu initialisiert (Schritte %1)</translation>
    </message>
    <message>
        <source>first evolution of the next scan</source>
        <translation>erste Entwicklung des nächsten Zyklus</translation>
    </message>
    <message>
        <source>Until stable: the next scan&apos;s first evolution is explained; later evolutions of the same scan follow with edges FALSE.</source>
        <translation>Bis stabil: Erklärt wird die erste Entwicklung des nächsten Zyklus; weitere Entwicklungen desselben Zyklus folgen mit Flanken FALSE.</translation>
    </message>
    <message>
        <source>One evolution per scan.</source>
        <translation>Eine Entwicklung pro Zyklus.</translation>
    </message>
    <message>
        <source>%1 (step %2): %3 ms of %4 ms</source>
        <extracomment>%1: a timer of a time-dependent receptivity; %2: its step; %3 of %4: elapsed and set time in ms</extracomment>
        <translation>%1 (Schritt %2): %3 ms von %4 ms</translation>
    </message>
    <message>
        <source>Outputs: %1</source>
        <extracomment>the outputs a nested GRAFCET drives, with their values (&quot;Spindle = TRUE, Marker = FALSE&quot;)</extracomment>
        <translation>Ausgänge: %1</translation>
    </message>
    <message>
        <source>T%1 (%2 → %3)</source>
        <extracomment>a transition of a nested GRAFCET: its number, upstream and downstream steps</extracomment>
        <translation>T%1 (%2 → %3)</translation>
    </message>
    <message>
        <source>Outputs and internal variables</source>
        <translation>Ausgänge und interne Variablen</translation>
    </message>
    <message>
        <source>Written by the program: %1 is not an input</source>
        <translation>Vom Programm geschrieben: %1 ist kein Eingang</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Show the previous scan of the history (%1); a scan or Run from a past scan continues from it and drops the later scans</source>
        <translation>Den vorherigen Zyklus des Verlaufs zeigen (%1); ein Zyklus oder Ausführen ab einem vergangenen Zyklus setzt bei ihm fort und verwirft die späteren Zyklen</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Vor</translation>
    </message>
    <message>
        <source>Show the next scan of the history (%1)</source>
        <translation>Den nächsten Zyklus des Verlaufs zeigen (%1)</translation>
    </message>
    <message>
        <source>Scan %1 of %2 (history) · %3 s</source>
        <extracomment>%1 of %2: the past scan shown and the latest scan run; %3: its simulated time in seconds</extracomment>
        <translation>Zyklus %1 von %2 (Verlauf) · %3 s</translation>
    </message>
    <message>
        <source>Replaying %1: scan %2 of %3.</source>
        <extracomment>%1: the scenario file; %2 of %3: the scan reached and the scenario&apos;s last scan</extracomment>
        <translation>%1 wird abgespielt: Zyklus %2 von %3.</translation>
    </message>
    <message>
        <source>Replay of %1: paused at scan %2 of %3. Press %4 to step, or Run to play the rest.</source>
        <extracomment>%1: the scenario file; %2 of %3: the scan reached and the scenario&apos;s last scan; %4: a key (F10)</extracomment>
        <translation>Abspielen von %1: angehalten bei Zyklus %2 von %3. %4 spielt einen Zyklus, Ausführen den Rest.</translation>
    </message>
    <message>
        <source>Unstable: the GRAFCET of %1 found no stable situation in this scan; its last evolution still fired.</source>
        <extracomment>Unstable is the name of the function block&apos;s output (not translated); %1: macro-steps or enclosing steps</extracomment>
        <translation>Unstable: der GRAFCET von %1 hat in diesem Zyklus keine stabile Situation erreicht; seine letzte Entwicklung hat noch geschaltet.</translation>
    </message>
    <message>
        <source>the condition of %1</source>
        <translation>der Bedingung von %1</translation>
    </message>
    <message>
        <source>the receptivity of T%1 of %2</source>
        <translation>der Weiterschaltbedingung von T%1 von %2</translation>
    </message>
    <message>
        <source>action %1 of step %2 of %3</source>
        <translation>Aktion %1 von Schritt %2 von %3</translation>
    </message>
    <message>
        <source>Stopped at scan %1: integer division by zero in %2 (%3 in &apos;%4&apos;). On the PLC the task stops with a fault; Reset to run again.</source>
        <translation>Angehalten in Zyklus %1: ganzzahlige Division durch null in %2 (%3 in &apos;%4&apos;). In der SPS hält die Task mit einem Fehler an; Zurücksetzen, um erneut zu starten.</translation>
    </message>
    <message numerus="yes">
        <source>%n other transition(s): an upstream step is not active</source>
        <extracomment>the transitions of a large nested GRAFCET left out of the explanation</extracomment>
        <translation>
            <numerusform>%n weiterer Übergang: ein vorgelagerter Schritt ist nicht aktiv</numerusform>
            <numerusform>%n weitere Übergänge: ein vorgelagerter Schritt ist nicht aktiv</numerusform>
        </translation>
    </message>
    <message>
        <source>Sensors (set by the machine)</source>
        <translation>Sensoren (von der Maschine gesetzt)</translation>
    </message>
    <message>
        <source>Written by the machine: %1 is a sensor of %2</source>
        <translation>Von der Maschine geschrieben: %1 ist ein Sensor von %2</translation>
    </message>
    <message>
        <source>It sets the machine&apos;s sensors itself: played in open loop, the machine stands still.</source>
        <translation>Es setzt die Sensoren der Maschine selbst: im offenen Regelkreis abgespielt, die Maschine steht still.</translation>
    </message>
    <message>
        <source>Right-click to inject a fault</source>
        <translation>Rechtsklick, um einen Fehler einzuspeisen</translation>
    </message>
</context>
<context>
    <name>editor::SimulationSession</name>
    <message>
        <source>(%1 more)</source>
        <translation>(%1 weitere)</translation>
    </message>
    <message>
        <source>%1 is a sensor of the machine&apos;s %2: the machine sets it</source>
        <translation>%1 ist ein Sensor von %2 der Maschine: die Maschine setzt ihn</translation>
    </message>
    <message>
        <source>The replay plays the machine&apos;s faults: stop it first</source>
        <translation>Die Wiedergabe spielt die Fehler der Maschine: zuerst anhalten</translation>
    </message>
    <message>
        <source>A fault needs the virtual machine running in closed loop</source>
        <translation>Ein Fehler braucht die virtuelle Maschine im geschlossenen Regelkreis</translation>
    </message>
</context>
<context>
    <name>editor::StPreviewDock</name>
    <message>
        <source>Structured Text</source>
        <translation>Strukturierter Text (ST)</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialekt:</translation>
    </message>
    <message>
        <source>IEC 61131-3</source>
        <translation>IEC 61131-3</translation>
    </message>
    <message>
        <source>CODESYS</source>
        <translation>CODESYS</translation>
    </message>
    <message>
        <source>Beremiz, OpenPLC, TwinCAT, matiec: globals in the configuration</source>
        <translation>Beremiz, OpenPLC, TwinCAT, matiec: globale Variablen in der Konfiguration</translation>
    </message>
    <message>
        <source>CODESYS V3.5: globals in the list GVL, read as GVL.Name</source>
        <translation>CODESYS V3.5: globale Variablen in der Liste GVL, gelesen als GVL.Name</translation>
    </message>
    <message>
        <source>The flavour of the generated code; saved with the model</source>
        <translation>Die Variante des generierten Codes; wird mit dem Modell gespeichert</translation>
    </message>
    <message>
        <source>%1 is hidden: it generates no code.</source>
        <translation>%1 ist ausgeblendet: Es wird kein Code generiert.</translation>
    </message>
    <message>
        <source>This transition is not effective: it generates no code.</source>
        <translation>Diese Transition ist nicht wirksam: Es wird kein Code generiert.</translation>
    </message>
    <message>
        <source>%1 generates no function block: only a visible macro-step or enclosing step does.</source>
        <translation>%1 erzeugt keinen Funktionsbaustein: das tut nur ein sichtbarer Makroschritt oder einschließender Schritt.</translation>
    </message>
    <message>
        <source>%1_FB (the nested GRAFCET of %1)</source>
        <extracomment>the function block shown: &quot;F1_FB (the nested GRAFCET of F1)&quot;</extracomment>
        <translation>%1_FB (der eingebettete GRAFCET von %1)</translation>
    </message>
    <message>
        <source>No enabled state runs this GRAFCET: it generates no function block.</source>
        <translation>Kein aktivierter Zustand führt dieses GRAFCET aus: Es erzeugt keinen Funktionsbaustein.</translation>
    </message>
    <message>
        <source>%1 is disabled in this unit mode: the mode&apos;s state machine has no branch for it.</source>
        <translation>%1 ist in dieser Betriebsart deaktiviert: Der Zustandsautomat der Betriebsart hat keinen Zweig dafür.</translation>
    </message>
</context>
<context>
    <name>editor::StartGuide</name>
    <message>
        <source>Getting started</source>
        <translation>Erste Schritte</translation>
    </message>
    <message>
        <source>&lt;b&gt;Hide&lt;/b&gt; what your machine does not need: select states or transitions and press Delete (Shift+Delete shows them again).</source>
        <translation>&lt;b&gt;Ausblenden&lt;/b&gt;, was Ihre Maschine nicht braucht: Zustände oder Transitionen auswählen und Entf drücken (Umschalt+Entf blendet sie wieder ein).</translation>
    </message>
    <message>
        <source>&lt;b&gt;Declare&lt;/b&gt; the buttons, sensors and actuators in the Variables panel below.</source>
        <translation>&lt;b&gt;Deklarieren&lt;/b&gt; Sie Taster, Sensoren und Aktoren im Bereich Variablen darunter.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Write&lt;/b&gt; each transition&apos;s condition: select the transition and press Enter. Red marks what is not finished yet.</source>
        <translation>&lt;b&gt;Schreiben&lt;/b&gt; Sie die Bedingung jeder Transition: Transition auswählen und Eingabe drücken. Rot markiert, was noch nicht fertig ist.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Simulate&lt;/b&gt; with F5, &lt;b&gt;verify&lt;/b&gt; with F7, then export PLCopen XML for your PLC.</source>
        <translation>&lt;b&gt;Simulieren&lt;/b&gt; mit F5, &lt;b&gt;verifizieren&lt;/b&gt; mit F7, dann PLCopen XML für Ihre SPS exportieren.</translation>
    </message>
    <message>
        <source>The chart is the GEMMA sheet: the ways your machine stops (A), works (F) and fails (D), and the transitions between them.</source>
        <translation>Das Diagramm ist das GEMMA-Blatt: wie Ihre Maschine anhält (A), arbeitet (F) und ausfällt (D), und die Transitionen dazwischen.</translation>
    </message>
    <message>
        <source>Select a step or a transition to edit it here.</source>
        <translation>Wählen Sie einen Schritt oder eine Transition, um sie hier zu bearbeiten.</translation>
    </message>
    <message>
        <source>Open an Example</source>
        <translation>Beispiel öffnen</translation>
    </message>
    <message>
        <source>A finished model to look at and simulate, opened as an untitled copy</source>
        <translation>Ein fertiges Modell zum Ansehen und Simulieren, als unbenannte Kopie geöffnet</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <source>How to build a model step by step (F1)</source>
        <translation>Wie man Schritt für Schritt ein Modell erstellt (F1)</translation>
    </message>
</context>
<context>
    <name>editor::StepDock</name>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Select a step in the chart to see and edit its properties.</source>
        <translation>Wählen Sie einen Schritt im Diagramm, um seine Eigenschaften zu sehen und zu bearbeiten.</translation>
    </message>
    <message>
        <source>Simple step: no nested behaviour.
Macro-step: its transitions wait until the nested behaviour is complete.
Enclosing step: its transitions fire whatever the nested behaviour is doing.</source>
        <translation>Einfacher Schritt: kein untergeordneter Ablauf.
Makroschritt: Seine Transitionen warten, bis der untergeordnete Ablauf abgeschlossen ist.
Einschließender Schritt: Seine Transitionen schalten unabhängig davon, was der untergeordnete Ablauf gerade tut.</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Typ:</translation>
    </message>
    <message>
        <source>&amp;Initial</source>
        <translation>&amp;Anfangsschritt</translation>
    </message>
    <message>
        <source>&amp;Hidden</source>
        <translation>Aus&amp;geblendet</translation>
    </message>
    <message>
        <source>A hidden step is not part of this machine: it generates no code, and its transitions are not effective.</source>
        <translation>Ein ausgeblendeter Schritt gehört nicht zu dieser Maschine: Er erzeugt keinen Code, und seine Transitionen sind nicht wirksam.</translation>
    </message>
    <message>
        <source>What this state does on this machine</source>
        <translation>Was dieser Zustand bei dieser Maschine bewirkt</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Kommentar:</translation>
    </message>
    <message>
        <source>Incoming transitions</source>
        <translation>Eingehende Transitionen</translation>
    </message>
    <message>
        <source>Outgoing transitions, by priority</source>
        <translation>Ausgehende Transitionen, nach Priorität</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transition</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Bedingung</translation>
    </message>
    <message>
        <source>Click a transition to select it</source>
        <translation>Klicken Sie auf eine Transition, um sie auszuwählen</translation>
    </message>
    <message>
        <source>%1 · state number %2</source>
        <translation>%1 · Zustandsnummer %2</translation>
    </message>
    <message>
        <source>%1 is the initial step. There is always exactly one initial step: to change it, make another step initial.</source>
        <translation>%1 ist der Anfangsschritt. Es gibt immer genau einen Anfangsschritt: Um ihn zu ändern, machen Sie einen anderen Schritt zum Anfangsschritt.</translation>
    </message>
    <message>
        <source>Make %1 the initial step (the PLC starts in it). The current initial step is %2.</source>
        <translation>%1 zum Anfangsschritt machen (die SPS startet darin). Der aktuelle Anfangsschritt ist %2.</translation>
    </message>
    <message>
        <source>F (family) →</source>
        <extracomment>an incoming transition: its source, an arrow</extracomment>
        <translation>F (Familie) →</translation>
    </message>
    <message>
        <source>%1 →</source>
        <translation>%1 →</translation>
    </message>
    <message>
        <source>F: → %1</source>
        <extracomment>the family transition in the outgoing list of an F state</extracomment>
        <translation>F: → %1</translation>
    </message>
    <message>
        <source>%1: → %2</source>
        <extracomment>an outgoing transition: priority, arrow, target (&quot;1: → F4&quot;); – when it has none</extracomment>
        <translation>%1: → %2</translation>
    </message>
    <message>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <source>Family transition: evaluated before the own transitions of every visible F state.</source>
        <translation>Familientransition: wird vor den eigenen Transitionen jedes sichtbaren F-Zustands ausgewertet.</translation>
    </message>
    <message>
        <source>Negated</source>
        <translation>Negiert</translation>
    </message>
    <message>
        <source>Condition: %1</source>
        <translation>Bedingung: %1</translation>
    </message>
    <message>
        <source>Not effective (%1): generates no code.</source>
        <translation>Nicht wirksam (%1): erzeugt keinen Code.</translation>
    </message>
    <message>
        <source>%1 (negated)</source>
        <extracomment>a negated transition in the Step dock&apos;s lists: the entry, then the mark</extracomment>
        <translation>%1 (negiert)</translation>
    </message>
    <message>
        <source>Open Nested GRAFCET</source>
        <translation>Eingebetteten GRAFCET öffnen</translation>
    </message>
    <message>
        <source>Show the nested GRAFCET of this step in a tab beside the GEMMA chart (double-click the step on the chart does the same)</source>
        <translation>Den eingebetteten GRAFCET dieses Schritts in einem Reiter neben dem GEMMA-Diagramm zeigen (ein Doppelklick auf den Schritt im Diagramm tut dasselbe)</translation>
    </message>
</context>
<context>
    <name>editor::StepItem</name>
    <message>
        <source>Simple step</source>
        <translation>Einfacher Schritt</translation>
    </message>
    <message>
        <source>Macro-step</source>
        <translation>Makroschritt</translation>
    </message>
    <message>
        <source>Enclosing step</source>
        <translation>Einschließender Schritt</translation>
    </message>
    <message>
        <source>%1, initial</source>
        <translation>%1, Anfangsschritt</translation>
    </message>
    <message>
        <source>%1, hidden</source>
        <translation>%1, ausgeblendet</translation>
    </message>
    <message numerus="yes">
        <source>Has a nested GRAFCET (%n steps)</source>
        <translation>
            <numerusform>Hat einen eingebetteten GRAFCET (%n Schritt)</numerusform>
            <numerusform>Hat einen eingebetteten GRAFCET (%n Schritte)</numerusform>
        </translation>
    </message>
    <message>
        <source>Its GRAFCET runs: steps %1 active</source>
        <extracomment>simulation; %1: the active steps of the nested GRAFCET (&quot;3, 5&quot;)</extracomment>
        <translation>Sein GRAFCET läuft: Schritte %1 aktiv</translation>
    </message>
    <message>
        <source>Its nested GRAFCET has 1 problem</source>
        <translation>Sein eingebetteter GRAFCET hat 1 Problem</translation>
    </message>
    <message numerus="yes">
        <source>Its nested GRAFCET has %n problems</source>
        <translation>
            <numerusform>Sein eingebetteter GRAFCET hat %n Problem</numerusform>
            <numerusform>Sein eingebetteter GRAFCET hat %n Probleme</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::TraceTableModel</name>
    <message>
        <source>Scan</source>
        <translation>Zyklus</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Fired</source>
        <translation>Geschaltet</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Entry</translation>
    </message>
    <message>
        <source>Tokens TRUE</source>
        <translation>Merker TRUE</translation>
    </message>
    <message>
        <source>Changed inputs</source>
        <translation>Geänderte Eingänge</translation>
    </message>
</context>
<context>
    <name>editor::TransitionDock</name>
    <message>
        <source>Transition</source>
        <translation>Transition</translation>
    </message>
    <message>
        <source>Select a transition in the chart to see and edit its condition.</source>
        <translation>Wählen Sie eine Transition im Diagramm, um ihre Bedingung zu sehen und zu bearbeiten.</translation>
    </message>
    <message>
        <source>Click a step to select it</source>
        <translation>Klicken Sie auf einen Schritt, um ihn auszuwählen</translation>
    </message>
    <message>
        <source>C&amp;ondition:</source>
        <translation>&amp;Bedingung:</translation>
    </message>
    <message>
        <source>e.g. Start AND NOT Stop</source>
        <translation>z. B. Start AND NOT Stop</translation>
    </message>
    <message>
        <source>Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND (&amp;), XOR, OR, comparisons and arithmetic.
Ctrl+Space completes a variable name.</source>
        <translation>Strukturierter Text: deklarierte Variablen, Zahlen, TRUE, FALSE, NOT, AND (&amp;), XOR, OR, Vergleiche und Arithmetik.
Strg+Leertaste vervollständigt einen Variablennamen.</translation>
    </message>
    <message>
        <source>&amp;Priority:</source>
        <translation>&amp;Priorität:</translation>
    </message>
    <message>
        <source>&amp;Negated</source>
        <translation>&amp;Negiert</translation>
    </message>
    <message>
        <source>Negation flips when this transition waits for the nested behaviour of its source:
a negated transition out of a macro-step ignores Complete;
a negated transition out of an enclosing step waits for Complete.</source>
        <translation>Die Negation kehrt um, ob diese Transition auf den untergeordneten Ablauf ihres Quellschritts wartet:
Eine negierte Transition aus einem Makroschritt ignoriert Complete;
eine negierte Transition aus einem einschließenden Schritt wartet auf Complete.</translation>
    </message>
    <message>
        <source>&amp;Hidden</source>
        <translation>&amp;Ausgeblendet</translation>
    </message>
    <message>
        <source>A hidden transition is not part of this machine: it generates no code.</source>
        <translation>Eine ausgeblendete Transition gehört nicht zu dieser Maschine: Sie erzeugt keinen Code.</translation>
    </message>
    <message>
        <source>Tokens</source>
        <translation>Merker</translation>
    </message>
    <message>
        <source>F (family)</source>
        <translation>F (Familie)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <extracomment>a transition: source step, arrow, target step</extracomment>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Not effective (%1): generates no code.</source>
        <translation>Nicht wirksam (%1): erzeugt keinen Code.</translation>
    </message>
    <message>
        <source>First</source>
        <translation>Erste</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <source>The family transition is evaluated before the own transitions of every visible F state.</source>
        <translation>Die Familientransition wird vor den eigenen Transitionen jedes sichtbaren F-Zustands ausgewertet.</translation>
    </message>
    <message>
        <source>Only effective transitions have a priority: show this transition and both its steps first.</source>
        <translation>Nur wirksame Transitionen haben eine Priorität: Blenden Sie zuerst diese Transition und ihre beiden Schritte ein.</translation>
    </message>
    <message>
        <source> of %1</source>
        <extracomment>after the priority in its spin box: &quot;2 of 5&quot;</extracomment>
        <translation> von %1</translation>
    </message>
    <message>
        <source>1 is evaluated first among the effective transitions out of %1; the others move to make room.</source>
        <translation>1 wird unter den wirksamen Transitionen aus %1 zuerst ausgewertet; die anderen rücken nach, um Platz zu machen.</translation>
    </message>
    <message>
        <source>Negation has no effect here: family transitions never wait for Complete.</source>
        <translation>Die Negation ist hier wirkungslos: Familientransitionen warten nie auf Complete.</translation>
    </message>
    <message>
        <source>Negation has no effect here: %1 is a simple step, and only transitions out of macro-steps and enclosing steps wait for Complete.</source>
        <translation>Die Negation ist hier wirkungslos: %1 ist ein einfacher Schritt, und nur Transitionen aus Makroschritten und einschließenden Schritten warten auf Complete.</translation>
    </message>
    <message>
        <source>Fires without waiting for the nested behaviour of macro-step %1 to complete.</source>
        <translation>Schaltet, ohne auf den Abschluss des untergeordneten Ablaufs von Makroschritt %1 zu warten.</translation>
    </message>
    <message>
        <source>Waits until the nested behaviour of macro-step %1 is complete (%1.Complete). Negate it to fire at once.</source>
        <translation>Wartet, bis der untergeordnete Ablauf von Makroschritt %1 abgeschlossen ist (%1.Complete). Negieren, um sofort zu schalten.</translation>
    </message>
    <message>
        <source>Waits until the nested behaviour of enclosing step %1 is complete (%1.Complete).</source>
        <translation>Wartet, bis der untergeordnete Ablauf des einschließenden Schritts %1 abgeschlossen ist (%1.Complete).</translation>
    </message>
    <message>
        <source>Fires whatever the nested behaviour of enclosing step %1 is doing. Negate it to wait for %1.Complete.</source>
        <translation>Schaltet unabhängig davon, was der untergeordnete Ablauf des einschließenden Schritts %1 gerade tut. Negieren, um auf %1.Complete zu warten.</translation>
    </message>
    <message>
        <source>Token on %1 (compared: no polarity)</source>
        <translation>Merker auf %1 (verglichen: keine Polarität)</translation>
    </message>
    <message>
        <source>Token on %1 (both NO and NC)</source>
        <translation>Merker auf %1 (sowohl Schließer als auch Öffner)</translation>
    </message>
    <message>
        <source>Token on %1 (NC)</source>
        <translation>Merker auf %1 (Öffner)</translation>
    </message>
    <message>
        <source>Token on %1 (NO)</source>
        <translation>Merker auf %1 (Schließer)</translation>
    </message>
    <message>
        <source>A token replaces a literal %1 or NOT %1: rewrite the condition so that %1 has one polarity.</source>
        <translation>Ein Merker ersetzt ein Literal %1 oder NOT %1: Schreiben Sie die Bedingung so um, dass %1 nur eine Polarität hat.</translation>
    </message>
    <message>
        <source>Normally closed: remembers that %1 was FALSE while the nested behaviour of %2 was not complete.</source>
        <translation>Öffner: merkt sich, dass %1 FALSE war, während der untergeordnete Ablauf von %2 nicht abgeschlossen war.</translation>
    </message>
    <message>
        <source>Normally open: remembers that %1 was TRUE while the nested behaviour of %2 was not complete.</source>
        <translation>Schließer: merkt sich, dass %1 TRUE war, während der untergeordnete Ablauf von %2 nicht abgeschlossen war.</translation>
    </message>
    <message>
        <source>Generated as %1_%2_%3_MEM.</source>
        <translation>Generiert als %1_%2_%3_MEM.</translation>
    </message>
    <message>
        <source>Token on %1 (not a BOOL variable of the condition)</source>
        <translation>Merker auf %1 (keine BOOL-Variable der Bedingung)</translation>
    </message>
    <message>
        <source>Uncheck to remove this token.</source>
        <translation>Abwählen, um diesen Merker zu entfernen.</translation>
    </message>
    <message>
        <source>Family transitions never wait for Complete, so tokens do not apply to them.</source>
        <translation>Familientransitionen warten nie auf Complete, daher gelten Merker für sie nicht.</translation>
    </message>
    <message>
        <source>Tokens apply to transitions out of macro-steps and enclosing steps; %1 is a simple step.</source>
        <translation>Merker gelten für Transitionen aus Makroschritten und einschließenden Schritten; %1 ist ein einfacher Schritt.</translation>
    </message>
    <message>
        <source>Correct the condition to choose its tokens.</source>
        <translation>Korrigieren Sie die Bedingung, um ihre Merker zu wählen.</translation>
    </message>
    <message>
        <source>The condition uses no BOOL variable.</source>
        <translation>Die Bedingung verwendet keine BOOL-Variable.</translation>
    </message>
    <message>
        <source>A token keeps a short pulse of a BOOL variable that occurs while the nested behaviour of %1 is not yet complete.</source>
        <translation>Ein Merker hält einen kurzen Impuls einer BOOL-Variablen fest, der auftritt, während der untergeordnete Ablauf von %1 noch nicht abgeschlossen ist.</translation>
    </message>
</context>
<context>
    <name>editor::TransitionItem</name>
    <message>
        <source>Family transition: applies to every F state</source>
        <translation>Familientransition: gilt für jeden F-Zustand</translation>
    </message>
    <message>
        <source>Priority %1</source>
        <translation>Priorität %1</translation>
    </message>
    <message>
        <source>Not effective (hidden)</source>
        <translation>Nicht wirksam (ausgeblendet)</translation>
    </message>
    <message>
        <source>%1, negated</source>
        <translation>%1, negiert</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Bedingung:</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>leer</translation>
    </message>
    <message>
        <source>Tokens: %1</source>
        <translation>Merker: %1</translation>
    </message>
</context>
<context>
    <name>editor::UserGuide</name>
    <message>
        <source>GG Studio User Guide</source>
        <translation>GG Studio – Benutzerhandbuch</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Vor</translation>
    </message>
    <message>
        <source>Getting Started</source>
        <translation>Erste Schritte</translation>
    </message>
</context>
<context>
    <name>editor::VariablesDock</name>
    <message>
        <source>Variables</source>
        <translation>Variablen</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filter</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>Duplicate the selected variables</source>
        <translation>Die ausgewählten Variablen duplizieren</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <source>Move the current variable up (declaration order)</source>
        <translation>Die aktuelle Variable nach oben verschieben (Deklarationsreihenfolge)</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <source>Move the current variable down (declaration order)</source>
        <translation>Die aktuelle Variable nach unten verschieben (Deklarationsreihenfolge)</translation>
    </message>
    <message>
        <source>Sort by Name</source>
        <translation>Nach Name sortieren</translation>
    </message>
    <message>
        <source>Sort the declarations by name (one undo step)</source>
        <translation>Die Deklarationen nach Name sortieren (ein Rückgängig-Schritt)</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopieren</translation>
    </message>
    <message>
        <source>Paste</source>
        <translation>Einfügen</translation>
    </message>
    <message>
        <source>Variable%1</source>
        <translation>Variable%1</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n variables</source>
        <translation>
            <numerusform>%n Variable entfernen</numerusform>
            <numerusform>%n Variablen entfernen</numerusform>
        </translation>
    </message>
    <message>
        <source>Sort variables by name</source>
        <translation>Variablen nach Name sortieren</translation>
    </message>
    <message>
        <source>Remove the selected variables</source>
        <translation>Die ausgewählten Variablen entfernen</translation>
    </message>
    <message>
        <source>Copy the selected variables as tab-separated rows</source>
        <translation>Die ausgewählten Variablen als tabulatorgetrennte Zeilen kopieren</translation>
    </message>
    <message>
        <source>Show only the variables whose name, type, kind, default or comment contains this text</source>
        <translation>Nur die Variablen zeigen, deren Name, Typ, Art, Anfangswert oder Kommentar diesen Text enthält</translation>
    </message>
    <message>
        <source>Add a BOOL variable after the current one (Insert)</source>
        <translation>Eine BOOL-Variable nach der aktuellen hinzufügen (Einfg)</translation>
    </message>
    <message>
        <source>Paste rows from a spreadsheet: name, type, default, comment and kind, in this order or in the order a first row of column titles gives</source>
        <translation>Zeilen aus einer Tabellenkalkulation einfügen: Name, Typ, Anfangswert, Kommentar und Art, in dieser Reihenfolge oder in der, die eine erste Zeile mit Spaltentiteln angibt</translation>
    </message>
</context>
<context>
    <name>editor::VariablesTableModel</name>
    <message>
        <source>No default: the PLC starts with %1.</source>
        <translation>Kein Anfangswert: Die SPS startet mit %1.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a supported type: use one of %2.</source>
        <translation>&apos;%1&apos; ist kein unterstützter Typ: Verwenden Sie einen von %2.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Anfangswert</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Kommentar</translation>
    </message>
    <message>
        <source>IEC 61131-3 identifier, unique ignoring case. Renaming updates every condition.</source>
        <translation>Bezeichner nach IEC 61131-3, eindeutig ohne Beachtung der Groß-/Kleinschreibung. Umbenennen aktualisiert jede Bedingung.</translation>
    </message>
    <message>
        <source>Elementary IEC 61131-3 type</source>
        <translation>Elementarer Datentyp nach IEC 61131-3</translation>
    </message>
    <message>
        <source>Initial value, a literal of the type; empty for the type&apos;s implicit default</source>
        <translation>Anfangswert, ein Literal des Typs; leer für den impliziten Standardwert des Typs</translation>
    </message>
    <message>
        <source>Free text, written into the generated declarations</source>
        <translation>Freier Text, wird in die generierten Deklarationen geschrieben</translation>
    </message>
    <message>
        <source>Line %1: the name is empty.</source>
        <translation>Zeile %1: Der Name ist leer.</translation>
    </message>
    <message>
        <source>Line %1: &apos;%2&apos; is not a supported type: use one of %3.</source>
        <translation>Zeile %1: &apos;%2&apos; ist kein unterstützter Typ: Verwenden Sie einen von %3.</translation>
    </message>
    <message>
        <source>There are no variables to paste: copy rows of name, type, default and comment, separated by tabs.</source>
        <translation>Es gibt keine Variablen zum Einfügen: Kopieren Sie Zeilen mit Name, Typ, Anfangswert und Kommentar, getrennt durch Tabulatoren.</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Internal</source>
        <translation>Intern</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Eingang</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a kind: use %2, %3 or %4.</source>
        <translation>&apos;%1&apos; ist keine Art: Verwenden Sie %2, %3 oder %4.</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Input: read from the machine. Output: written by the actions of nested GRAFCETs. Internal: a memory the program writes and reads.</source>
        <translation>Eingang: von der Maschine gelesen. Ausgang: von den Aktionen eingebetteter GRAFCETs geschrieben. Intern: ein Speicher, den das Programm schreibt und liest.</translation>
    </message>
    <message>
        <source>Line %1: &apos;%2&apos; is not a kind: use input, output or internal.</source>
        <translation>Zeile %1: &apos;%2&apos; ist keine Art: Verwenden Sie Eingang, Ausgang oder Intern.</translation>
    </message>
</context>
<context>
    <name>editor::VerificationPanel</name>
    <message>
        <source>&amp;Verify</source>
        <translation>&amp;Verifizieren</translation>
    </message>
    <message>
        <source>&amp;Show on Chart</source>
        <translation>Im &amp;Diagramm zeigen</translation>
    </message>
    <message>
        <source>&amp;Replay in Simulator</source>
        <translation>Im &amp;Simulator abspielen</translation>
    </message>
    <message>
        <source>Explore every input sequence of the GEMMA layer and report what cannot happen</source>
        <translation>Alle Eingangsfolgen der GEMMA-Ebene durchsuchen und melden, was nicht eintreten kann</translation>
    </message>
    <message>
        <source>Select the element of the finding on the chart</source>
        <translation>Das Element des Befunds im Diagramm auswählen</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Element</translation>
    </message>
    <message>
        <source>Scans</source>
        <translation>Zyklen</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>Scans of the counterexample, which the simulator can replay</source>
        <translation>Zyklen des Gegenbeispiels, das der Simulator abspielen kann</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <source>Verifying…</source>
        <translation>Verifikation läuft…</translation>
    </message>
    <message>
        <source>Verification failed: %1.</source>
        <translation>Verifikation fehlgeschlagen: %1.</translation>
    </message>
    <message>
        <source>Not verified yet.</source>
        <translation>Noch nicht verifiziert.</translation>
    </message>
    <message>
        <source>Model changed since verification: verify again to update the findings.</source>
        <translation>Das Modell wurde seit der Verifikation geändert: Erneut verifizieren, um die Befunde zu aktualisieren.</translation>
    </message>
    <message>
        <source>Some properties do not hold (%1 configurations explored).</source>
        <translation>Einige Eigenschaften gelten nicht (%1 Konfigurationen untersucht).</translation>
    </message>
    <message>
        <source>Every property holds; see the notes (%1 configurations explored).</source>
        <translation>Alle Eigenschaften gelten; siehe die Hinweise (%1 Konfigurationen untersucht).</translation>
    </message>
    <message>
        <source>Every property holds (%1 configurations explored).</source>
        <translation>Alle Eigenschaften gelten (%1 Konfigurationen untersucht).</translation>
    </message>
    <message>
        <source>The model changed since verification: verify again to replay</source>
        <translation>Das Modell wurde seit der Verifikation geändert: Zum Abspielen erneut verifizieren</translation>
    </message>
    <message>
        <source>Start the simulation and replay the scans that lead to the finding</source>
        <translation>Die Simulation starten und die Zyklen abspielen, die zum Befund führen</translation>
    </message>
    <message>
        <source>Complete settings changed since verification: verify again to update the findings.</source>
        <translation>Die Complete-Einstellungen wurden seit der Verifikation geändert: Erneut verifizieren, um die Befunde zu aktualisieren.</translation>
    </message>
    <message>
        <source>All Complete outputs free</source>
        <translation>Alle Complete-Ausgänge frei</translation>
    </message>
    <message>
        <source>Assumed Complete automatic: %1</source>
        <translation>Complete als automatisch angenommen: %1</translation>
    </message>
    <message>
        <source>Free: the nested behaviour may complete at any scan, or never. Automatic: Complete is TRUE at every scan, as the skeleton function block. Verify assumes automatic the nested steps whose Complete is Automatic in the Simulation dock while the simulation runs; all others are free.</source>
        <translation>Frei: Der untergeordnete Ablauf kann in jedem Zyklus abgeschlossen sein oder nie. Automatisch: Complete ist in jedem Zyklus TRUE, wie beim Gerüst-Funktionsbaustein. Die Verifikation nimmt die Schritte als automatisch an, deren Complete im Simulationsfenster während der Simulation auf Automatisch steht; alle anderen sind frei.</translation>
    </message>
    <message>
        <source>%1: T%2</source>
        <translation>%1: T%2</translation>
    </message>
    <message>
        <source>%1: step %2</source>
        <extracomment>A step of a nested GRAFCET: %1 the GEMMA step, %2 its number</extracomment>
        <translation>%1: Schritt %2</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>%1: nested GRAFCET</source>
        <extracomment>The row that groups the findings about the nested GRAFCET of a GEMMA step, e.g. &quot;F1 Normal production&quot;</extracomment>
        <translation>%1: eingebetteter GRAFCET</translation>
    </message>
    <message>
        <source>The findings about the nested GRAFCET of %1</source>
        <translation>Die Befunde zum eingebetteten GRAFCET von %1</translation>
    </message>
    <message>
        <source>Some properties do not hold (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Einige Eigenschaften gelten nicht (%1 Konfigurationen der GEMMA-Ebene und %2 Programmzustände beider Ebenen erkundet).</translation>
    </message>
    <message>
        <source>Every property holds; see the notes (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Alle Eigenschaften gelten; siehe die Hinweise (%1 Konfigurationen der GEMMA-Ebene und %2 Programmzustände beider Ebenen erkundet).</translation>
    </message>
    <message>
        <source>Every property holds (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Alle Eigenschaften gelten (%1 Konfigurationen der GEMMA-Ebene und %2 Programmzustände beider Ebenen erkundet).</translation>
    </message>
    <message>
        <source>The exploration of both layers abstracted:</source>
        <translation>Die Erkundung beider Ebenen hat abstrahiert:</translation>
    </message>
    <message>
        <source>Exact time switched on since verification: verify again to update the findings.</source>
        <translation>Exakte Zeit seit der Verifikation eingeschaltet: Erneut verifizieren, um die Befunde zu aktualisieren.</translation>
    </message>
    <message>
        <source>Exact time switched off since verification: verify again to update the findings.</source>
        <translation>Exakte Zeit seit der Verifikation ausgeschaltet: Erneut verifizieren, um die Befunde zu aktualisieren.</translation>
    </message>
    <message>
        <source>Exact time</source>
        <translation>Exakte Zeit</translation>
    </message>
    <message>
        <source>Exact time: every timer elapses exactly when the PLC&apos;s would, counted in scans (Simulation &gt; Verify with Exact Time).</source>
        <translation>Exakte Zeit: Jeder Timer läuft genau dann ab, wenn der der SPS ablaufen würde, in Zyklen gezählt (Simulation &gt; Mit exakter Zeit verifizieren).</translation>
    </message>
    <message>
        <source>Nothing is violated, but some properties are undecided: see the findings (%1 configurations explored).</source>
        <translation>Nichts ist verletzt, aber einige Eigenschaften sind unentschieden: siehe die Befunde (%1 Konfigurationen untersucht).</translation>
    </message>
    <message>
        <source>Nothing is violated, but some properties are undecided: see the findings (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Nichts ist verletzt, aber einige Eigenschaften sind unentschieden: siehe die Befunde (%1 Konfigurationen der GEMMA-Ebene und %2 Programmzustände beider Ebenen erkundet).</translation>
    </message>
    <message>
        <source>&amp;Time limit:</source>
        <translation>&amp;Zeitlimit:</translation>
    </message>
    <message>
        <source> s</source>
        <extracomment>The unit after the verification&apos;s time limit: &quot;4 s&quot;</extracomment>
        <translation> s</translation>
    </message>
    <message>
        <source>How long a verification may run. Past it, what is not decided yet is reported as undecided (GV100) with how far the exploration got: give more time and verify again.</source>
        <translation>Wie lange eine Verifikation laufen darf. Danach wird, was noch nicht entschieden ist, als unentschieden (GV100) gemeldet, mit dem Stand der Exploration: geben Sie mehr Zeit und verifizieren Sie erneut.</translation>
    </message>
    <message>
        <source>The machine is used since verification: verify again to update the findings.</source>
        <translation>Die Maschine wird seit der Verifikation verwendet: erneut verifizieren, um die Befunde zu aktualisieren.</translation>
    </message>
    <message>
        <source>The machine is no longer used since verification: verify again to update the findings.</source>
        <translation>Die Maschine wird seit der Verifikation nicht mehr verwendet: erneut verifizieren, um die Befunde zu aktualisieren.</translation>
    </message>
    <message>
        <source>With the machine</source>
        <translation>Mit der Maschine</translation>
    </message>
    <message>
        <source>With the machine: the sensors the model&apos;s machine drives follow it, scan by scan, instead of taking any value (Simulation &gt; Verify with the Machine).</source>
        <translation>Mit der Maschine: Die Sensoren, die die Maschine des Modells setzt, folgen ihr Zyklus für Zyklus, statt jeden Wert anzunehmen (Simulation &gt; Mit der Maschine verifizieren).</translation>
    </message>
    <message>
        <source>Single faults switched on since verification: verify again to update the findings.</source>
        <translation>Einzelne Fehler seit der Verifikation eingeschaltet: erneut verifizieren, um die Befunde zu aktualisieren.</translation>
    </message>
    <message>
        <source>Single faults switched off since verification: verify again to update the findings.</source>
        <translation>Einzelne Fehler seit der Verifikation ausgeschaltet: erneut verifizieren, um die Befunde zu aktualisieren.</translation>
    </message>
    <message>
        <source>Single faults</source>
        <translation>Einzelne Fehler</translation>
    </message>
    <message>
        <source>Single faults: any one sensor stuck or flickering, or one cylinder or conveyor jammed, from any scan on (Simulation &gt; Verify with Single Faults).</source>
        <translation>Einzelne Fehler: ein beliebiger Sensor, der hängt oder flackert, oder ein blockierter Zylinder oder Förderer, ab jedem Zyklus (Simulation &gt; Mit einzelnen Fehlern verifizieren).</translation>
    </message>
</context>
<context>
    <name>editor::ZoomIndicator</name>
    <message>
        <source>Zoom: %1 %</source>
        <translation>Zoom: %1 %</translation>
    </message>
    <message>
        <source>The zoom of the tab in front. Ctrl+wheel or a pinch zooms about the mouse; Ctrl+0 fits the drawing in the window, Ctrl+1 shows it at its actual size</source>
        <translation>Der Zoom des vorderen Tabs. Strg+Mausrad oder eine Zwei-Finger-Geste zoomt um den Mauszeiger; Strg+0 passt die Zeichnung ins Fenster ein, Strg+1 zeigt sie in Originalgröße</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Editor for the GEMMA-GRAFCET method of specifying machine operating modes</source>
        <translation>Editor für die GEMMA-GRAFCET-Methode zur Spezifikation der Betriebsarten von Maschinen</translation>
    </message>
    <message>
        <source>The model file to open (GG Studio JSON, GG-Generator JSON or GG Studio PLCopen XML).</source>
        <translation>Die zu öffnende Modelldatei (GG-Studio-JSON, GG-Generator-JSON oder GG-Studio-PLCopen-XML).</translation>
    </message>
</context>
<context>
    <name>modbus::ModbusLink</name>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation>kann nicht auf %1:%2 lauschen: %3</translation>
    </message>
    <message>
        <source>cannot connect to %1:%2: %3</source>
        <translation>keine Verbindung zu %1:%2: %3</translation>
    </message>
    <message>
        <source>write of %1 %2..%3 to %4:%5</source>
        <translation>Schreiben von %1 %2..%3 nach %4:%5</translation>
    </message>
    <message>
        <source>read of %1 %2..%3 from %4:%5</source>
        <translation>Lesen von %1 %2..%3 von %4:%5</translation>
    </message>
</context>
</TS>
