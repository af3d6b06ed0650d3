<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it_IT">
<context>
    <name>AddGrafcetActionCommand</name>
    <message>
        <source>Add action %1 to %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Aggiungi l’azione %1 alla tappa %3 di %2</translation>
    </message>
</context>
<context>
    <name>AddMachineComponentCommand</name>
    <message>
        <source>Add %1 %2</source>
        <extracomment>%1: a kind of machine component (&quot;Conveyor&quot;); %2: its name</extracomment>
        <translation>Aggiungi %1 %2</translation>
    </message>
</context>
<context>
    <name>AddModeCommand</name>
    <message>
        <source>Add mode %1 %2</source>
        <translation>Aggiungi il modo %1 %2</translation>
    </message>
</context>
<context>
    <name>AddPropertyCommand</name>
    <message>
        <source>Add property</source>
        <translation>Aggiungi proprietà</translation>
    </message>
</context>
<context>
    <name>AddVariableCommand</name>
    <message>
        <source>Add variable %1</source>
        <translation>Aggiungi la variabile %1</translation>
    </message>
</context>
<context>
    <name>ChartExport</name>
    <message>
        <source>GEMMA-GRAFCET chart drawn by GG Studio</source>
        <translation>Diagramma GEMMA-GRAFCET disegnato con GG Studio</translation>
    </message>
</context>
<context>
    <name>ConditionErrorText</name>
    <message>
        <source>comments are not allowed in a condition</source>
        <translation>i commenti non sono ammessi in una condizione</translation>
    </message>
    <message>
        <source>use = to compare; := is assignment</source>
        <translation>usare = per confrontare; := è l&apos;assegnazione</translation>
    </message>
    <message>
        <source>use = to compare; == is not Structured Text</source>
        <translation>usare = per confrontare; == non è Structured Text</translation>
    </message>
    <message>
        <source>use &lt;&gt; for &apos;not equal&apos;</source>
        <translation>usare &lt;&gt; per &apos;diverso da&apos;</translation>
    </message>
    <message>
        <source>use NOT for negation</source>
        <translation>usare NOT per la negazione</translation>
    </message>
    <message>
        <source>use AND (or &amp;) for &apos;and&apos;</source>
        <translation>usare AND (o &amp;) per &apos;e&apos;</translation>
    </message>
    <message>
        <source>use OR for &apos;or&apos;</source>
        <translation>usare OR per &apos;o&apos;</translation>
    </message>
    <message>
        <source>&apos;**&apos; (power) is not supported in a condition</source>
        <translation>&apos;**&apos; (potenza) non è supportato in una condizione</translation>
    </message>
    <message>
        <source>&apos;;&apos; is not allowed in a condition: write only the expression</source>
        <translation>&apos;;&apos; non è ammesso in una condizione: scrivere solo l&apos;espressione</translation>
    </message>
    <message>
        <source>the text contains bytes that are not valid UTF-8</source>
        <translation>il testo contiene byte che non sono UTF-8 valido</translation>
    </message>
    <message>
        <source>&apos;%1&apos; contains a non-ASCII character: names use ASCII letters, digits and _ only</source>
        <translation>&apos;%1&apos; contiene un carattere non ASCII: i nomi usano solo lettere ASCII, cifre e _</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not supported: write plain decimal numbers, TRUE or FALSE (no typed, based or time literals)</source>
        <translation>&apos;%1&apos; non è supportato: scrivere numeri decimali semplici, TRUE o FALSE (niente letterali tipizzati, in base o di tempo)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: qualified names are not allowed, write the variable name alone</source>
        <translation>&apos;%1&apos;: i nomi qualificati non sono ammessi, scrivere solo il nome della variabile</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid number</source>
        <translation>&apos;%1&apos; non è un numero valido</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: write only the boolean expression, without IF ... THEN</source>
        <extracomment>%1: IF, THEN, ELSE... as written</extracomment>
        <translation>&apos;%1&apos; non è ammesso in una condizione: scrivere solo l&apos;espressione booleana, senza IF ... THEN</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: it is a type name</source>
        <translation>&apos;%1&apos; non è ammesso in una condizione: è un nome di tipo</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: it is an IEC 61131-3 keyword</source>
        <translation>&apos;%1&apos; non è ammesso in una condizione: è una parola chiave IEC 61131-3</translation>
    </message>
    <message>
        <source>unexpected control character (byte %1)</source>
        <extracomment>%1: the byte in hexadecimal (0x1B)</extracomment>
        <translation>carattere di controllo inatteso (byte %1)</translation>
    </message>
    <message>
        <source>unexpected character &apos;%1&apos;</source>
        <translation>carattere &apos;%1&apos; inatteso</translation>
    </message>
    <message>
        <source>condition too complex: operators nested more than %1 levels deep</source>
        <translation>condizione troppo complessa: operatori annidati su più di %1 livelli</translation>
    </message>
    <message>
        <source>condition nested too deeply: more than %1 levels of parentheses</source>
        <translation>condizione troppo annidata: più di %1 livelli di parentesi</translation>
    </message>
    <message>
        <source>condition nested too deeply: more than %1 levels of unary operators</source>
        <translation>condizione troppo annidata: più di %1 livelli di operatori unari</translation>
    </message>
    <message>
        <source>unmatched &apos;)&apos;: no &apos;(&apos; opens it</source>
        <translation>&apos;)&apos; senza corrispondenza: nessuna &apos;(&apos; la apre</translation>
    </message>
    <message>
        <source>expected an operand before &apos;%1&apos;</source>
        <extracomment>%1: an operator the condition starts with</extracomment>
        <translation>atteso un operando prima di &apos;%1&apos;</translation>
    </message>
    <message>
        <source>empty parentheses: expected an expression inside &apos;( )&apos;</source>
        <translation>parentesi vuote: attesa un&apos;espressione dentro &apos;( )&apos;</translation>
    </message>
    <message>
        <source>expected an operand after &apos;%1&apos;</source>
        <extracomment>%1: the operator or &apos;(&apos; the condition ends with</extracomment>
        <translation>atteso un operando dopo &apos;%1&apos;</translation>
    </message>
    <message>
        <source>expected an operand after &apos;%1&apos;, found &apos;%2&apos;</source>
        <extracomment>%1: an operator or &apos;(&apos;; %2: what follows it instead of an operand</extracomment>
        <translation>atteso un operando dopo &apos;%1&apos;, trovato &apos;%2&apos;</translation>
    </message>
    <message>
        <source>unmatched &apos;(&apos; at column %1: missing &apos;)&apos;</source>
        <extracomment>%1: a column number</extracomment>
        <translation>&apos;(&apos; senza corrispondenza alla colonna %1: manca &apos;)&apos;</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos;: expected an operator or &apos;)&apos; to close the &apos;(&apos; at column %2</source>
        <extracomment>%1: what was found; %2: the column of the &apos;(&apos;</extracomment>
        <translation>&apos;%1&apos; inatteso: atteso un operatore o &apos;)&apos; per chiudere la &apos;(&apos; alla colonna %2</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete condition</source>
        <translation>&apos;%1&apos; inatteso dopo una condizione completa</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete condition (missing operator?)</source>
        <translation>&apos;%1&apos; inatteso dopo una condizione completa (manca un operatore?)</translation>
    </message>
    <message>
        <source>an edge (RE, FE, ↑, ↓) applies to a variable name</source>
        <translation>un fronte (RE, FE, ↑, ↓) si applica a un nome di variabile</translation>
    </message>
    <message>
        <source>an edge (RE, FE, ↑, ↓) applies to a variable name, not to &apos;%1&apos;</source>
        <extracomment>%1: what follows RE, FE, ↑ or ↓ instead of a variable name</extracomment>
        <translation>un fronte (RE, FE, ↑, ↓) si applica a un nome di variabile, non a «%1»</translation>
    </message>
    <message>
        <source>the duration &apos;%1&apos; must be followed by /X&lt;step&gt;, as in %1/X3</source>
        <extracomment>%1: a duration such as 5s; X3 is step 3&apos;s activity, keep it as is</extracomment>
        <translation>la durata «%1» deve essere seguita da /X&lt;tappa&gt;, come in %1/X3</translation>
    </message>
    <message>
        <source>expected a step activity X&lt;step&gt; after &apos;/&apos; of the duration</source>
        <translation>attesa un&apos;attività di tappa X&lt;tappa&gt; dopo la «/» della durata</translation>
    </message>
    <message>
        <source>expected a step activity X&lt;step&gt; after &apos;/&apos; of the duration, found &apos;%1&apos;</source>
        <translation>attesa un&apos;attività di tappa X&lt;tappa&gt; dopo la «/» della durata, trovato «%1»</translation>
    </message>
    <message>
        <source>the duration &apos;%1&apos; is zero: write a positive duration</source>
        <translation>la durata «%1» è zero: scrivere una durata positiva</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid duration: write for example 200ms, 5s, 1m30s or T#5s (units d, h, m, s, ms, largest first)</source>
        <translation>«%1» non è una durata valida: scrivere per esempio 200ms, 5s, 1m30s o T#5s (unità d, h, m, s, ms, dalla più grande)</translation>
    </message>
    <message>
        <source>empty action: write for example Valve, S Valve, R Valve or Count := Count + 1</source>
        <translation>azione vuota: scrivere per esempio Valve, S Valve, R Valve o Count := Count + 1</translation>
    </message>
    <message>
        <source>an action writes a variable: &apos;%1&apos; is not a variable name</source>
        <translation>un&apos;azione scrive una variabile: «%1» non è un nome di variabile</translation>
    </message>
    <message>
        <source>the qualifier &apos;%1&apos; is not supported: use N (or none), S, R or an assignment V := value</source>
        <translation>il qualificatore «%1» non è supportato: usare N (o nessuno), S, R o un&apos;assegnazione V := valore</translation>
    </message>
    <message>
        <source>an assignment takes no qualifier: write V := value, without &apos;%1&apos;</source>
        <translation>un&apos;assegnazione non ha qualificatore: scrivere V := valore, senza «%1»</translation>
    </message>
    <message>
        <source>a stored action (%1) takes no IF condition: only continuous actions are conditional</source>
        <extracomment>%1: the qualifier S or R</extracomment>
        <translation>un&apos;azione memorizzata (%1) non ha condizione IF: solo le azioni continue sono condizionali</translation>
    </message>
    <message>
        <source>expected a value after &apos;:=&apos;</source>
        <translation>atteso un valore dopo «:=»</translation>
    </message>
    <message>
        <source>expected a condition after IF</source>
        <translation>attesa una condizione dopo IF</translation>
    </message>
    <message>
        <source>use := to assign a value; = compares</source>
        <translation>usare := per assegnare un valore; = confronta</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete action</source>
        <translation>«%1» inatteso dopo un&apos;azione completa</translation>
    </message>
    <message>
        <source>empty condition: write when the transition fires (TRUE if it is always ready), or hide the transition if the machine does not need it</source>
        <translation>condizione vuota: scrivere quando la transizione scatta (TRUE se è sempre pronta), oppure nascondere la transizione se la macchina non ne ha bisogno</translation>
    </message>
    <message>
        <source>a property starts with never or always</source>
        <translation>una proprietà inizia con never o always</translation>
    </message>
    <message>
        <source>a property starts with never or always, not &apos;%1&apos;</source>
        <translation>una proprietà inizia con never o always, non con &apos;%1&apos;</translation>
    </message>
    <message>
        <source>expected a GEMMA step after &apos;in&apos;</source>
        <translation>attesa una tappa GEMMA dopo &apos;in&apos;</translation>
    </message>
    <message>
        <source>expected a GEMMA step after &apos;in&apos;, found &apos;%1&apos;</source>
        <translation>attesa una tappa GEMMA dopo &apos;in&apos;, trovato &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>ConditionTypeErrorText</name>
    <message>
        <source>&apos;%1&apos; is an integer</source>
        <extracomment>%1: a subexpression of the condition</extracomment>
        <translation>&apos;%1&apos; è un intero</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a real number</source>
        <translation>&apos;%1&apos; è un numero reale</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is of unknown type</source>
        <translation>&apos;%1&apos; è di tipo sconosciuto</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is %2</source>
        <extracomment>%1: a subexpression of the condition; %2: its IEC type (INT, BOOL)</extracomment>
        <translation>&apos;%1&apos; è di tipo %2</translation>
    </message>
    <message>
        <source>a condition must be BOOL, but %1</source>
        <extracomment>%1: the condition and what it is (&quot;&apos;Speed + 1&apos; is an integer&quot;)</extracomment>
        <translation>una condizione deve essere BOOL, ma %1</translation>
    </message>
    <message>
        <source>%1 needs a BOOL operand, but %2</source>
        <extracomment>%1: NOT; %2: its operand and what it is (&quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 richiede un operando BOOL, ma %2</translation>
    </message>
    <message>
        <source>unary %1 needs a numeric operand, but %2</source>
        <extracomment>%1: &apos;-&apos; (negation); %2: its operand and what it is (&quot;&apos;Start&apos; is BOOL&quot;)</extracomment>
        <translation>il %1 unario richiede un operando numerico, ma %2</translation>
    </message>
    <message>
        <source>%1 needs BOOL operands, but %2</source>
        <extracomment>%1: AND, OR or XOR; %2: the operand at fault and what it is (&quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 richiede operandi BOOL, ma %2</translation>
    </message>
    <message>
        <source>%1 needs numeric operands, but %2</source>
        <extracomment>%1: a comparison or arithmetic operator (&apos;&lt;&apos;, &apos;+&apos;); %2: the operand at fault and what it is</extracomment>
        <translation>%1 richiede operandi numerici, ma %2</translation>
    </message>
    <message>
        <source>%1 needs integer operands, but %2</source>
        <extracomment>%1: MOD; %2: the operand at fault and what it is (&quot;&apos;Temp&apos; is REAL&quot;)</extracomment>
        <translation>%1 richiede operandi interi, ma %2</translation>
    </message>
    <message>
        <source>%1 needs two operands of the same kind, but %2 and %3</source>
        <extracomment>%1: &apos;=&apos; or &apos;&lt;&gt;&apos;; %2, %3: each operand and what it is (&quot;&apos;Start&apos; is BOOL&quot;, &quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 richiede due operandi dello stesso genere, ma %2 e %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range: integer literals go up to 9223372036854775807 (LINT)</source>
        <translation>&apos;%1&apos; è fuori intervallo: i letterali interi arrivano fino a 9223372036854775807 (LINT)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range for LREAL (-1.8E308..1.8E308)</source>
        <translation>&apos;%1&apos; è fuori dall&apos;intervallo di LREAL (-1.8E308..1.8E308)</translation>
    </message>
</context>
<context>
    <name>ConveyorItem</name>
    <message>
        <source>Parts out: %1</source>
        <translation>Pezzi usciti: %1</translation>
    </message>
</context>
<context>
    <name>DeclarationFixText</name>
    <message>
        <source>Declare &apos;%1&apos; as OUTPUT %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Dichiarare &apos;%1&apos; come uscita %2</translation>
    </message>
    <message>
        <source>Declare &apos;%1&apos; as INTERNAL %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Dichiarare &apos;%1&apos; come variabile interna %2</translation>
    </message>
    <message>
        <source>Declare &apos;%1&apos; as INPUT %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Dichiarare &apos;%1&apos; come ingresso %2</translation>
    </message>
</context>
<context>
    <name>DiagnosticText</name>
    <message>
        <source>the name is empty</source>
        <translation>il nome è vuoto</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid IEC 61131-3 identifier: use ASCII letters, digits and &apos;_&apos;, not starting with a digit</source>
        <translation>&apos;%1&apos; non è un identificatore IEC 61131-3 valido: usare lettere ASCII, cifre e &apos;_&apos;, senza iniziare con una cifra</translation>
    </message>
    <message>
        <source>&apos;%1&apos; contains &apos;__&apos;, which IEC 61131-3 identifiers may not</source>
        <translation>&apos;%1&apos; contiene &apos;__&apos;, non ammesso negli identificatori IEC 61131-3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; ends with &apos;_&apos;, which IEC 61131-3 identifiers may not</source>
        <translation>&apos;%1&apos; termina con &apos;_&apos;, non ammesso negli identificatori IEC 61131-3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is an IEC 61131-3 keyword or type name</source>
        <translation>&apos;%1&apos; è una parola chiave o un nome di tipo IEC 61131-3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a name the generated code uses</source>
        <translation>&apos;%1&apos; è un nome usato dal codice generato</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; does not occur in the condition.</source>
        <translation>La memoria su &apos;%2&apos; in %1 non è valida: &apos;%2&apos; non compare nella condizione.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is ambiguous: the condition uses both %2 and NOT %2, so the token could be neither normally open nor normally closed.</source>
        <translation>La memoria su &apos;%2&apos; in %1 è ambigua: la condizione usa sia %2 sia NOT %2, quindi la memoria non può essere né normalmente aperta né normalmente chiusa.</translation>
    </message>
    <message>
        <source>The token in %1 names &apos;%2&apos;, which is not a declared variable.</source>
        <translation>La memoria in %1 indica &apos;%2&apos;, che non è una variabile dichiarata.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; is compared with &apos;=&apos; or &apos;&lt;&gt;&apos; in the condition, where it has no polarity; a token can only replace a literal %2 or NOT %2.</source>
        <translation>La memoria su &apos;%2&apos; in %1 non è valida: nella condizione &apos;%2&apos; è confrontata con &apos;=&apos; o &apos;&lt;&gt;&apos;, dove non ha polarità; una memoria può sostituire solo un letterale %2 o NOT %2.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 has no effect and is not generated: family transitions never wait for Complete.</source>
        <translation>La memoria su &apos;%2&apos; in %1 non ha effetto e non viene generata: le transizioni di famiglia non attendono mai Complete.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 has no effect and is not generated: its source %3 is a simple step.</source>
        <translation>La memoria su &apos;%2&apos; in %1 non ha effetto e non viene generata: la sua tappa di origine %3 è una tappa semplice.</translation>
    </message>
    <message>
        <source>The initial step %1 is hidden: the PLC would start in a state that has no code.</source>
        <translation>La tappa iniziale %1 è nascosta: il PLC partirebbe in uno stato privo di codice.</translation>
    </message>
    <message>
        <source>Step %1 has no visible outgoing transition: the machine would stay in it forever.</source>
        <translation>La tappa %1 non ha transizioni uscenti visibili: la macchina vi resterebbe per sempre.</translation>
    </message>
    <message>
        <source>Step %1 has no visible incoming transition: it can never become active.</source>
        <translation>La tappa %1 non ha transizioni entranti visibili: non può mai diventare attiva.</translation>
    </message>
    <message>
        <source>The family transition %1 is negated, which has no effect: family transitions never wait for Complete.</source>
        <translation>La transizione di famiglia %1 è negata, il che non ha effetto: le transizioni di famiglia non attendono mai Complete.</translation>
    </message>
    <message>
        <source>The condition of %1 is FALSE: the transition can never fire (hide it instead).</source>
        <translation>La condizione di %1 è FALSE: la transizione non può mai scattare (meglio nasconderla).</translation>
    </message>
    <message>
        <source>Step %1 cannot be reached from the initial step %2 through visible transitions: it can never become active.</source>
        <translation>La tappa %1 non è raggiungibile dalla tappa iniziale %2 tramite transizioni visibili: non può mai diventare attiva.</translation>
    </message>
    <message>
        <source>Transition %1 is negated, which has no effect: its source %2 is a simple step, and negation only changes transitions out of macro and enclosing steps.</source>
        <translation>La transizione %1 è negata, il che non ha effetto: la sua tappa di origine %2 è una tappa semplice, e la negazione cambia solo le transizioni uscenti da macro-tappe e tappe incapsulanti.</translation>
    </message>
    <message>
        <source>The condition of %1 is TRUE and does not wait for Complete: the lower-priority transitions %2 can never fire.</source>
        <translation>La condizione di %1 è TRUE e non attende Complete: le transizioni a priorità inferiore %2 non possono mai scattare.</translation>
    </message>
    <message>
        <source>Invalid variable name: %1.</source>
        <translation>Nome di variabile non valido: %1.</translation>
    </message>
    <message>
        <source>Syntax error in the condition of %1: %2.</source>
        <translation>Errore di sintassi nella condizione di %1: %2.</translation>
    </message>
    <message>
        <source>In the condition of %1: &apos;%2&apos; is not a declared variable.</source>
        <translation>Nella condizione di %1: &apos;%2&apos; non è una variabile dichiarata.</translation>
    </message>
    <message>
        <source>Type error in the condition of %1: %2.</source>
        <translation>Errore di tipo nella condizione di %1: %2.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; is %3, and only BOOL variables can have a token.</source>
        <translation>La memoria su &apos;%2&apos; in %1 non è valida: &apos;%2&apos; è di tipo %3, e solo le variabili BOOL possono avere una memoria.</translation>
    </message>
    <message>
        <source>The default value of variable &apos;%1&apos; is invalid: %2.</source>
        <translation>Il valore iniziale della variabile &apos;%1&apos; non è valido: %2.</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Errore</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Avviso</translation>
    </message>
    <message>
        <source>Information</source>
        <translation>Informazione</translation>
    </message>
    <message>
        <source>The verification reached its time or size limit before every property was decided: the properties not reported were not decided.</source>
        <translation>La verifica ha raggiunto il suo limite di tempo o di dimensione prima di decidere tutte le proprietà: le proprietà non segnalate non sono state decise.</translation>
    </message>
    <message>
        <source>The verification reached its time or size limit before deciding everything about %1: what is not reported about it was not decided. Every other finding holds.</source>
        <translation>La verifica ha raggiunto il suo limite di tempo o di dimensione prima di decidere tutto su %1: ciò che non è segnalato al riguardo non è stato deciso. Tutti gli altri risultati valgono.</translation>
    </message>
    <message>
        <source>Step %1 can never become active: no effective transition leads to it.</source>
        <translation>La tappa %1 non può mai diventare attiva: nessuna transizione effettiva vi conduce.</translation>
    </message>
    <message>
        <source>Step %1 can never become active: no situation reachable from the initial step lets %2 fire.</source>
        <translation>La tappa %1 non può mai diventare attiva: nessuna situazione raggiungibile dalla tappa iniziale fa scattare %2.</translation>
    </message>
    <message>
        <source>Transition %1 can never fire: its condition is never TRUE in a situation reachable from the initial step.</source>
        <translation>La transizione %1 non può mai scattare: la sua condizione non è TRUE in nessuna situazione raggiungibile dalla tappa iniziale.</translation>
    </message>
    <message>
        <source>Transition %1 can never fire: whenever its condition holds, a transition of higher priority fires first (%2).</source>
        <translation>La transizione %1 non può mai scattare: ogni volta che la sua condizione è vera, scatta prima una transizione a priorità più alta (%2).</translation>
    </message>
    <message>
        <source>The condition of %1 is always TRUE: no own transition of an F step can ever fire.</source>
        <translation>La condizione di %1 è sempre TRUE: nessuna transizione propria di una tappa F può mai scattare.</translation>
    </message>
    <message>
        <source>The condition of %1 is always TRUE when %3 is active: %2 can never fire.</source>
        <translation>La condizione di %1 è sempre TRUE quando %3 è attiva: %2 non può mai scattare.</translation>
    </message>
    <message>
        <source>%1 and %2 can both be TRUE in the same scan: the priority decides, %1 fires.</source>
        <translation>%1 e %2 possono essere entrambe TRUE nello stesso ciclo: decide la priorità, scatta %1.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead to a situation from which the initial step can never become active again.</source>
        <translation>Una volta attiva %1, gli ingressi possono portare a una situazione da cui la tappa iniziale non può mai più diventare attiva.</translation>
    </message>
    <message>
        <source>Step %1 can get stuck: the inputs can lead to a situation in it from which no transition out of it can ever fire.</source>
        <translation>La tappa %1 può bloccarsi: gli ingressi possono portare a una situazione in cui nessuna delle sue transizioni uscenti può mai scattare.</translation>
    </message>
    <message>
        <source>The emergency stop D1 can never be entered from %1: the family transition F-&gt;D1 is not effective and %1 has no transition to D1.</source>
        <translation>L&apos;arresto di emergenza D1 non può mai essere raggiunto da %1: la transizione di famiglia F-&gt;D1 non è effettiva e %1 non ha transizioni verso D1.</translation>
    </message>
    <message>
        <source>In some situations of %1 the emergency stop D1 cannot be entered in one scan, whatever the inputs: %2 cannot fire there.</source>
        <translation>In alcune situazioni di %1 l&apos;arresto di emergenza D1 non può essere raggiunto in un ciclo, qualunque siano gli ingressi: %2 non vi può scattare.</translation>
    </message>
    <message>
        <source>Not confirmed: a condition uses a comparison the verifier cannot decide, and the counterexample does not replay.</source>
        <translation>Non confermato: una condizione usa un confronto che il verificatore non sa decidere, e il controesempio non si riproduce.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 has no initial step: it would never do anything.</source>
        <translation>Il GRAFCET annidato di %1 non ha tappa iniziale: non farebbe mai nulla.</translation>
    </message>
    <message>
        <source>Step %2 of %1 cannot be reached from the initial steps through transitions: it can never become active.</source>
        <translation>La tappa %2 di %1 non è raggiungibile dalle tappe iniziali tramite transizioni: non può mai diventare attiva.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 never sets Complete, so %2, which wait for it, can never fire.</source>
        <extracomment>%2: the GEMMA transitions that wait for Complete</extracomment>
        <translation>Il GRAFCET annidato di %1 non attiva mai Complete, quindi %2, che lo attendono, non possono mai scattare.</translation>
    </message>
    <message>
        <source>The selection after step %2 of %1 is not exclusive: %3 and %4 can both fire (with %5), and both branches then start.</source>
        <extracomment>%3, %4: two nested transitions; %5: the values that make both receptivities TRUE</extracomment>
        <translation>La selezione dopo la tappa %2 di %1 non è esclusiva: %3 e %4 possono scattare insieme (con %5), e allora partono entrambi i rami.</translation>
    </message>
    <message>
        <source>Step %2 of %1 has no outgoing transition and does not set Complete: the GRAFCET stops there for good.</source>
        <translation>La tappa %2 di %1 non ha transizione in uscita e non attiva Complete: il GRAFCET si ferma lì per sempre.</translation>
    </message>
    <message>
        <source>Under the until-stable rule, step %2 of %1 is left in the call that enters it (%3 is always TRUE): the GEMMA layer never sees what it does to Complete.</source>
        <translation>Con la regola «fino a stabilità», la tappa %2 di %1 viene lasciata nella stessa chiamata che la attiva (%3 è sempre vera): il livello GEMMA non vede mai cosa fa di Complete.</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has a name the code of the nested GRAFCETs uses: %2.</source>
        <extracomment>%2: why, in English (a technical reason)</extracomment>
        <translation>La variabile «%1» ha un nome che usa il codice dei GRAFCET annidati: %2.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 is kept but not used: %1 is hidden.</source>
        <translation>Il GRAFCET annidato di %1 è conservato ma non usato: %1 è nascosta.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 is kept but not used: %1 is a simple step.</source>
        <translation>Il GRAFCET annidato di %1 è conservato ma non usato: %1 è una tappa semplice.</translation>
    </message>
    <message>
        <source>The condition of %1 is empty: write when it fires (TRUE if it is always ready), or hide the transition if your machine does not need it.</source>
        <translation>La condizione di %1 è vuota: scrivere quando scatta (TRUE se è sempre pronta), oppure nascondere la transizione se la macchina non ne ha bisogno.</translation>
    </message>
    <message>
        <source>Step %2 of the nested GRAFCET of %1 can never become active.</source>
        <extracomment>%1: a GEMMA step; %2: the number of a step of its nested GRAFCET</extracomment>
        <translation>La tappa %2 del GRAFCET annidato di %1 non può mai diventare attiva.</translation>
    </message>
    <message>
        <source>Transition T%2 of the nested GRAFCET of %1 can never fire.</source>
        <extracomment>%1: a GEMMA step; %2: the number of a transition of its nested GRAFCET</extracomment>
        <translation>La transizione T%2 del GRAFCET annidato di %1 non può mai scattare.</translation>
    </message>
    <message>
        <source>Step %2 of the nested GRAFCET of %1 can be activated while it is already active: the GRAFCET is not safe.</source>
        <translation>La tappa %2 del GRAFCET annidato di %1 può essere attivata quando è già attiva: il GRAFCET non è sicuro.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 can be Unstable: its evolutions do not settle within one scan.</source>
        <translation>Il GRAFCET annidato di %1 può essere instabile (Unstable): le sue evoluzioni non si stabilizzano in un ciclo.</translation>
    </message>
    <message>
        <source>Transitions T%3 and T%4 of the nested GRAFCET of %1 can fire together from step %2: both branches of the selection start.</source>
        <extracomment>%2: a nested step; %3, %4: the numbers of two nested transitions</extracomment>
        <translation>Le transizioni T%3 e T%4 del GRAFCET annidato di %1 possono scattare insieme dalla tappa %2: partono entrambi i rami della selezione.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead its nested GRAFCET to a situation from which Complete never becomes TRUE.</source>
        <translation>Una volta attiva %1, gli ingressi possono portare il suo GRAFCET annidato in una situazione da cui Complete non diventa mai TRUE.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead its nested GRAFCET to a situation from which Complete never becomes TRUE: %2 can no longer fire.</source>
        <extracomment>%2: the GEMMA transitions that wait for Complete</extracomment>
        <translation>Una volta attiva %1, gli ingressi possono portare il suo GRAFCET annidato in una situazione da cui Complete non diventa mai TRUE: %2 non può più scattare.</translation>
    </message>
    <message>
        <source>%1 waits for the Complete of %2, which never becomes TRUE: it can never fire.</source>
        <translation>%1 attende il Complete di %2, che non diventa mai TRUE: non può mai scattare.</translation>
    </message>
    <message>
        <source>Steps %2 and %3 of the nested GRAFCET of %1 can write different values to &apos;%4&apos; in the same scan: the result depends on the order of the actions.</source>
        <translation>Le tappe %2 e %3 del GRAFCET annidato di %1 possono scrivere valori diversi in &apos;%4&apos; nello stesso ciclo: il risultato dipende dall&apos;ordine delle azioni.</translation>
    </message>
    <message>
        <source>The continuous output &apos;%2&apos; can still be TRUE in the scan in which the emergency stop %1 is entered.</source>
        <translation>L&apos;uscita continua &apos;%2&apos; può essere ancora TRUE nel ciclo in cui si entra nell&apos;arresto di emergenza %1.</translation>
    </message>
    <message>
        <source>The stored output &apos;%2&apos; can still be TRUE in the scan in which the emergency stop %1 is entered: stored actions are memories, only continuous outputs drop with the state.</source>
        <translation>L&apos;uscita memorizzata &apos;%2&apos; può essere ancora TRUE nel ciclo in cui si entra nell&apos;arresto di emergenza %1: le azioni memorizzate sono memorie, solo le uscite continue cadono con lo stato.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; does not hold.</source>
        <translation>La proprietà &apos;%1&apos; non è soddisfatta.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; holds in every reachable scan, with the abstractions the verification lists.</source>
        <translation>La proprietà &apos;%1&apos; è soddisfatta in ogni ciclo raggiungibile, con le astrazioni indicate dalla verifica.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; holds in every reachable scan.</source>
        <translation>La proprietà &apos;%1&apos; è soddisfatta in ogni ciclo raggiungibile.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; cannot be checked: it is empty.</source>
        <translation>La proprietà &apos;%1&apos; non può essere verificata: è vuota.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; cannot be checked: %2.</source>
        <extracomment>%2: why, in English (the property checker&apos;s message)</extracomment>
        <translation>La proprietà &apos;%1&apos; non può essere verificata: %2.</translation>
    </message>
    <message>
        <source>The exploration of both layers reached its time or size limit: what it found is reported, but nothing about the nested GRAFCETs or the properties is proved.</source>
        <translation>L&apos;esplorazione dei due livelli ha raggiunto il suo limite di tempo o di dimensione: quanto trovato è segnalato, ma nulla è dimostrato sui GRAFCET annidati né sulle proprietà.</translation>
    </message>
    <message>
        <source>Not confirmed: the run found under the abstractions of the verification does not replay in the simulator.</source>
        <translation>Non confermato: l&apos;esecuzione trovata con le astrazioni della verifica non si riproduce nel simulatore.</translation>
    </message>
    <message>
        <source>Not confirmed: decided on the GEMMA layer with every Complete free, and the run does not replay with the nested GRAFCETs.</source>
        <translation>Non confermato: deciso sul livello GEMMA con ogni Complete libero, e l&apos;esecuzione non si riproduce con i GRAFCET annidati.</translation>
    </message>
    <message>
        <source>In the condition of %1: &apos;%2&apos; divides by zero: on the PLC an integer division or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / 0)</extracomment>
        <translation>Nella condizione di %1: &apos;%2&apos; divide per zero: sul PLC una divisione intera o un MOD per zero arresta il task con un errore, e una divisione REAL dà INF o NaN.</translation>
    </message>
    <message>
        <source>In the condition of %1: the divisor of &apos;%2&apos; can be zero: an integer division or MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / Batch)</extracomment>
        <translation>Nella condizione di %1: il divisore di &apos;%2&apos; può essere zero: una divisione intera o un MOD per zero arresta il PLC con un errore (e la simulazione), una divisione REAL dà INF o NaN.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; is undecided: neither proved nor shown violated (%2).</source>
        <extracomment>%2: why, in English (the verifier&apos;s reason)</extracomment>
        <translation>La proprietà &apos;%1&apos; è indecisa: né dimostrata né mostrata violata (%2).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the function block of enclosing step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variabile &apos;%1&apos; ha il nome del blocco funzionale della tappa incapsulante %2 nel codice generato: rinominare la variabile (per esempio in &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the function block of macro-step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variabile &apos;%1&apos; ha il nome del blocco funzionale della macro-tappa %2 nel codice generato: rinominare la variabile (per esempio in &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the instance of enclosing step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variabile &apos;%1&apos; ha il nome dell&apos;istanza della tappa incapsulante %2 nel codice generato: rinominare la variabile (per esempio in &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the instance of macro-step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variabile &apos;%1&apos; ha il nome dell&apos;istanza della macro-tappa %2 nel codice generato: rinominare la variabile (per esempio in &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Enclosing step %1 declares its function block %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La tappa incapsulante %1 dichiara il suo blocco funzionale %2 nel codice generato, e la variabile &apos;%3&apos; ha quel nome: rinominare la variabile (per esempio in &apos;%4&apos;), o rendere %1 una tappa semplice.</translation>
    </message>
    <message>
        <source>Macro-step %1 declares its function block %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La macro-tappa %1 dichiara il suo blocco funzionale %2 nel codice generato, e la variabile &apos;%3&apos; ha quel nome: rinominare la variabile (per esempio in &apos;%4&apos;), o rendere %1 una tappa semplice.</translation>
    </message>
    <message>
        <source>Enclosing step %1 declares its instance %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La tappa incapsulante %1 dichiara la sua istanza %2 nel codice generato, e la variabile &apos;%3&apos; ha quel nome: rinominare la variabile (per esempio in &apos;%4&apos;), o rendere %1 una tappa semplice.</translation>
    </message>
    <message>
        <source>Macro-step %1 declares its instance %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La macro-tappa %1 dichiara la sua istanza %2 nel codice generato, e la variabile &apos;%3&apos; ha quel nome: rinominare la variabile (per esempio in &apos;%4&apos;), o rendere %1 una tappa semplice.</translation>
    </message>
    <message>
        <source>%2 is read in %3 and by its level in %4, which can fire right after it: while %2 stays TRUE, both fire in the same scan and step %5 of %1 is passed through; read its rising edge in %4 (↑%2) so that each press fires one transition.</source>
        <extracomment>%2: a BOOL input; %3, %4: two nested transitions; %5: the steps between them</extracomment>
        <translation>%2 è letta in %3 e per livello in %4, che può scattare subito dopo: finché %2 resta TRUE, entrambe scattano nello stesso ciclo e la tappa %5 di %1 viene attraversata; leggere il suo fronte di salita in %4 (↑%2) perché ogni pressione faccia scattare una sola transizione.</translation>
    </message>
    <message>
        <source>%2 is read in %3 and by its level in %4, which can fire right after it: while %2 stays TRUE, both fire in consecutive scans and step %5 of %1 is passed through; read its rising edge in %4 (↑%2) so that each press fires one transition.</source>
        <translation>%2 è letta in %3 e per livello in %4, che può scattare subito dopo: finché %2 resta TRUE, entrambe scattano in cicli consecutivi e la tappa %5 di %1 viene attraversata; leggere il suo fronte di salita in %4 (↑%2) perché ogni pressione faccia scattare una sola transizione.</translation>
    </message>
    <message>
        <source>The selection after step %2 of %1 is not complete: with %4 none of %3 fires and the GRAFCET waits in step %2; add a branch for these values unless waiting is intended.</source>
        <extracomment>%3: the branches (T1, T2); %4: values of the variables (CP1 = TRUE, CP2 = FALSE)</extracomment>
        <translation>La selezione dopo la tappa %2 di %1 non è completa: con %4 non scatta nessuna di %3 e il GRAFCET attende nella tappa %2; aggiungere un ramo per questi valori, a meno che l&apos;attesa non sia voluta.</translation>
    </message>
    <message>
        <source>Not confirmed: its counterexample does not replay to it in the simulator.</source>
        <translation>Non confermato: il suo controesempio non lo riproduce nel simulatore.</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; is used by no condition, receptivity or action that generates code.</source>
        <translation>La variabile &apos;%1&apos; non è usata da alcuna condizione, recettività o azione che genera codice.</translation>
    </message>
    <message>
        <source>Not confirmed: the run found under the abstractions of the verification does not replay in the simulator, and the search for one with time counted in scans stopped at the time or size limit (a longer time limit may find it).</source>
        <translation>Non confermato: l&apos;esecuzione trovata con le astrazioni della verifica non si riproduce nel simulatore, e la ricerca di una con il tempo contato in cicli si è fermata al limite di tempo o di dimensione (un limite di tempo più lungo può trovarla).</translation>
    </message>
</context>
<context>
    <name>EditMachineComponentCommand</name>
    <message>
        <source>Edit %1</source>
        <translation>Modifica %1</translation>
    </message>
</context>
<context>
    <name>ElementLabels</name>
    <message>
        <source>F (family)</source>
        <translation>F (famiglia)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <extracomment>a transition: source step, arrow, target step</extracomment>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Simple step</source>
        <translation>Tappa semplice</translation>
    </message>
    <message>
        <source>Macro-step</source>
        <translation>Macro-tappa</translation>
    </message>
    <message>
        <source>Enclosing step</source>
        <translation>Tappa incapsulante</translation>
    </message>
    <message>
        <source>hidden</source>
        <translation>nascosta</translation>
    </message>
    <message>
        <source>source %1 hidden</source>
        <translation>tappa di origine %1 nascosta</translation>
    </message>
    <message>
        <source>target %1 hidden</source>
        <translation>tappa di destinazione %1 nascosta</translation>
    </message>
</context>
<context>
    <name>ExampleModels</name>
    <message>
        <source>Drilling Cell</source>
        <translation>Cella di foratura</translation>
    </message>
    <message>
        <source>A machine that clamps, drills and marks parts: GEMMA states with four nested GRAFCETs, ready to simulate</source>
        <translation>Una macchina che blocca, fora e marca i pezzi: stati GEMMA con quattro GRAFCET annidati, pronta da simulare</translation>
    </message>
    <message>
        <source>Drilling Cell with Mistakes</source>
        <translation>Cella di foratura con errori</translation>
    </message>
    <message>
        <source>The same machine with one mistake for each check of the nested GRAFCETs, to see what the Problems panel reports</source>
        <translation>La stessa macchina con un errore per ogni controllo dei GRAFCET annidati, per vedere che cosa segnala il pannello Problemi</translation>
    </message>
    <message>
        <source>The example %1 is missing from this build.</source>
        <translation>L&apos;esempio %1 manca in questa build.</translation>
    </message>
    <message>
        <source>Bottle Filler (PackML)</source>
        <translation>Riempitrice di bottiglie (PackML)</translation>
    </message>
    <message>
        <source>A PackML unit with Production and Manual modes and a GRAFCET in Resetting, Starting, Execute, Stopping and Aborting</source>
        <translation>Un&apos;unità PackML con i modi Production e Manual e un GRAFCET in Resetting, Starting, Execute, Stopping e Aborting</translation>
    </message>
</context>
<context>
    <name>FaultMenu</name>
    <message>
        <source>Fault not injected</source>
        <translation>Guasto non iniettato</translation>
    </message>
    <message>
        <source>stuck at TRUE</source>
        <extracomment>a fault of a sensor of the virtual machine, shown beside its value</extracomment>
        <translation>bloccato a TRUE</translation>
    </message>
    <message>
        <source>stuck at FALSE</source>
        <translation>bloccato a FALSE</translation>
    </message>
    <message>
        <source>flickering</source>
        <translation>intermittente</translation>
    </message>
    <message>
        <source>stuck TRUE</source>
        <extracomment>a sensor&apos;s fault where space is short (the Machine tab); TRUE and FALSE stay as they are</extracomment>
        <translation>bloccato TRUE</translation>
    </message>
    <message>
        <source>stuck FALSE</source>
        <translation>bloccato FALSE</translation>
    </message>
    <message>
        <source>flicker</source>
        <translation>intermittente</translation>
    </message>
    <message>
        <source>Fault of %1</source>
        <extracomment>%1: a sensor variable of the virtual machine
----------
%1: a cylinder or conveyor of the virtual machine</extracomment>
        <translation>Guasto di %1</translation>
    </message>
    <message>
        <source>Stuck at &amp;TRUE</source>
        <translation>Bloccato a &amp;TRUE</translation>
    </message>
    <message>
        <source>Stuck at &amp;FALSE</source>
        <translation>Bloccato a &amp;FALSE</translation>
    </message>
    <message>
        <source>F&amp;licker</source>
        <translation>&amp;Intermittente</translation>
    </message>
    <message>
        <source>&amp;Clear Fault</source>
        <translation>&amp;Rimuovi il guasto</translation>
    </message>
    <message>
        <source>Clear &amp;Jam</source>
        <translation>&amp;Sblocca</translation>
    </message>
    <message>
        <source>&amp;Jam</source>
        <translation>&amp;Blocca</translation>
    </message>
</context>
<context>
    <name>GrafcetClipboard</name>
    <message>
        <source>The clipboard holds no GRAFCET steps</source>
        <translation>Gli appunti non contengono tappe di GRAFCET</translation>
    </message>
    <message>
        <source>Nothing pasted: the GRAFCET steps on the clipboard are damaged (%1)</source>
        <extracomment>%1 what is wrong in the clipboard&apos;s data (in English), with where when known</extracomment>
        <translation>Non è stato incollato nulla: le tappe di GRAFCET negli appunti sono danneggiate (%1)</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Tappa %1</translation>
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
        <translation>GRAFCET annidato disegnato con GG Studio</translation>
    </message>
</context>
<context>
    <name>InitialStepRule</name>
    <message>
        <source>%1 is the initial step, which cannot be hidden; make another step initial first</source>
        <extracomment>%1 is a GEMMA step, e.g. A1</extracomment>
        <translation>%1 è la fase iniziale, che non può essere nascosta; rendere prima iniziale un&apos;altra fase</translation>
    </message>
    <message>
        <source>%1 is hidden and cannot be the initial step; show it first</source>
        <extracomment>%1 is a GEMMA step, e.g. A3</extracomment>
        <translation>%1 è nascosta e non può essere la fase iniziale; mostrarla prima</translation>
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
        <translation>(non cablato)</translation>
    </message>
    <message>
        <source>%1, jammed</source>
        <extracomment>%1: the kind of a machine component (&quot;Double-acting cylinder&quot;), which a fault has stopped</extracomment>
        <translation>%1, bloccato</translation>
    </message>
</context>
<context>
    <name>MachineDiagnosticText</name>
    <message>
        <source>an input</source>
        <translation>un ingresso</translation>
    </message>
    <message>
        <source>an output</source>
        <translation>un&apos;uscita</translation>
    </message>
    <message>
        <source>an internal variable</source>
        <translation>una variabile interna</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal names &apos;%3&apos;, which is no variable of the model.</source>
        <extracomment>%1: a machine component; %2: its role (extend, retracted...); %3: a name</extracomment>
        <translation>Il segnale %2 di %1 indica &apos;%3&apos;, che non è una variabile del modello.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal is %3, %4; it needs %5.</source>
        <extracomment>%1: a machine component; %2: its role; %3: a variable; %4, %5: &quot;an input&quot;, &quot;an output&quot;...</extracomment>
        <translation>Il segnale %2 di %1 è %3, %4; serve %5.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal is %3, of type %4; a machine signal is BOOL.</source>
        <extracomment>%4: an IEC type (INT)</extracomment>
        <translation>Il segnale %2 di %1 è %3, di tipo %4; un segnale della macchina è BOOL.</translation>
    </message>
    <message>
        <source>%3 is wired to %1&apos;s %2 signal and to %4&apos;s %5 signal: an input has one source.</source>
        <extracomment>%1, %4: machine components; %2, %5: their roles; %3: the input both are wired to</extracomment>
        <translation>%3 è collegato al segnale %2 di %1 e al segnale %5 di %4: un ingresso ha una sola sorgente.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal %3 is driven by no action of the program: the component never moves.</source>
        <translation>Il segnale %2 (%3) di %1 non è comandato da nessuna azione del programma: il componente non si muove mai.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 is %3: out of range (travel times 1 to 3600000 ms, delays 0 to 3600000 ms, parts 0 to 1000000000).</source>
        <extracomment>%2: a parameter (extendMs, onDelayMs, parts); %3: its value</extracomment>
        <translation>%2 di %1 vale %3: fuori intervallo (tempi di corsa da 1 a 3600000 ms, ritardi da 0 a 3600000 ms, pezzi da 0 a 1000000000).</translation>
    </message>
    <message>
        <source>%1 has no variable for its %2 signal.</source>
        <translation>%1 non ha una variabile per il suo segnale %2.</translation>
    </message>
    <message>
        <source>%1 feeds &apos;%2&apos;, which is no conveyor of the machine.</source>
        <translation>%1 alimenta &apos;%2&apos;, che non è un nastro trasportatore della macchina.</translation>
    </message>
</context>
<context>
    <name>MachineText</name>
    <message>
        <source>Double-acting cylinder</source>
        <translation>Cilindro a doppio effetto</translation>
    </message>
    <message>
        <source>Single-acting cylinder</source>
        <translation>Cilindro a semplice effetto</translation>
    </message>
    <message>
        <source>Conveyor</source>
        <translation>Nastro trasportatore</translation>
    </message>
    <message>
        <source>Lamp</source>
        <translation>Spia</translation>
    </message>
    <message>
        <source>Push button</source>
        <translation>Pulsante</translation>
    </message>
    <message>
        <source>Selector</source>
        <translation>Selettore</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Arresto di emergenza</translation>
    </message>
    <message>
        <source>Delayed sensor</source>
        <translation>Sensore ritardato</translation>
    </message>
    <message>
        <source>Part source</source>
        <translation>Sorgente di pezzi</translation>
    </message>
    <message>
        <source>extend</source>
        <translation>estendere</translation>
    </message>
    <message>
        <source>retract</source>
        <translation>ritrarre</translation>
    </message>
    <message>
        <source>retracted</source>
        <translation>ritratto</translation>
    </message>
    <message>
        <source>extended</source>
        <translation>esteso</translation>
    </message>
    <message>
        <source>run</source>
        <translation>marcia</translation>
    </message>
    <message>
        <source>part present</source>
        <translation>pezzo presente</translation>
    </message>
    <message>
        <source>lamp</source>
        <translation>spia</translation>
    </message>
    <message>
        <source>input</source>
        <translation>ingresso</translation>
    </message>
    <message>
        <source>output</source>
        <translation>uscita</translation>
    </message>
    <message>
        <source>sensor</source>
        <translation>sensore</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>vuoto</translation>
    </message>
    <message>
        <source>Extend time (ms)</source>
        <translation>Tempo di estensione (ms)</translation>
    </message>
    <message>
        <source>Retract time (ms)</source>
        <translation>Tempo di ritrazione (ms)</translation>
    </message>
    <message>
        <source>Travel time (ms)</source>
        <translation>Tempo di percorrenza (ms)</translation>
    </message>
    <message>
        <source>On delay (ms)</source>
        <translation>Ritardo all&apos;attivazione (ms)</translation>
    </message>
    <message>
        <source>Off delay (ms)</source>
        <translation>Ritardo alla disattivazione (ms)</translation>
    </message>
    <message>
        <source>Parts</source>
        <translation>Pezzi</translation>
    </message>
    <message>
        <source>Normally closed</source>
        <translation>Normalmente chiuso</translation>
    </message>
    <message>
        <source>Normally open</source>
        <translation>Normalmente aperto</translation>
    </message>
</context>
<context>
    <name>MoveGrafcetActionCommand</name>
    <message>
        <source>Move action %1 of %2 step %3 up</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Sposta su l’azione %1 della tappa %3 di %2</translation>
    </message>
    <message>
        <source>Move action %1 of %2 step %3 down</source>
        <translation>Sposta giù l’azione %1 della tappa %3 di %2</translation>
    </message>
</context>
<context>
    <name>MovePropertyCommand</name>
    <message>
        <source>Move property %1</source>
        <translation>Sposta la proprietà %1</translation>
    </message>
</context>
<context>
    <name>MoveVariableCommand</name>
    <message>
        <source>Move variable %1</source>
        <translation>Sposta la variabile %1</translation>
    </message>
</context>
<context>
    <name>NestedProblemText</name>
    <message>
        <source>the receptivity of T%2 of %1</source>
        <extracomment>%1: a GEMMA step; %2: the number of a transition of its nested GRAFCET</extracomment>
        <translation>recettività di T%2 di %1</translation>
    </message>
    <message>
        <source>action %3 of step %2 of %1</source>
        <extracomment>%1: a GEMMA step; %2: a nested step&apos;s number; %3: the action&apos;s position in its list, from 1</extracomment>
        <translation>azione %3 della tappa %2 di %1</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is not a declared variable.</source>
        <translation>In %1: &apos;%2&apos; non è una variabile dichiarata.</translation>
    </message>
    <message>
        <source>In %1: a continuous action is N V or V IF &lt;condition&gt;.</source>
        <translation>In %1: un&apos;azione continua è N V o V IF &lt;condizione&gt;.</translation>
    </message>
    <message>
        <source>In %1: a stored action is S V, R V or V := &lt;expression&gt;.</source>
        <translation>In %1: un&apos;azione memorizzata è S V, R V o V := &lt;espressione&gt;.</translation>
    </message>
    <message>
        <source>Syntax error in %1: %2.</source>
        <translation>Errore di sintassi in %1: %2.</translation>
    </message>
    <message>
        <source>Type error in %1: %2.</source>
        <translation>Errore di tipo in %1: %2.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is %3; this action needs a BOOL variable.</source>
        <extracomment>%3: an IEC type name (INT)</extracomment>
        <translation>In %1: &apos;%2&apos; è %3; questa azione richiede una variabile BOOL.</translation>
    </message>
    <message>
        <source>In %1: %4 does not fit &apos;%2&apos; (%3): it cannot be assigned to it.</source>
        <extracomment>%2: the target variable; %3: its type; %4: the value as written</extracomment>
        <translation>In %1: %4 non è adatto a &apos;%2&apos; (%3): non gli può essere assegnato.</translation>
    </message>
    <message>
        <source>In %1: %2 names step %3, which the GRAFCET of %4 does not have.</source>
        <extracomment>%2: a step activity as written (X9); %3: its step number; %4: the GEMMA step</extracomment>
        <translation>In %1: %2 nomina la tappa %3, che il GRAFCET di %4 non ha.</translation>
    </message>
    <message>
        <source>In %1: %2 is longer than %3, the longest duration an IEC TIME (a TON preset) holds.</source>
        <extracomment>%2: a duration as written (25d/X1); %3: the longest IEC TIME</extracomment>
        <translation>In %1: %2 è più lungo di %3, la durata più lunga che un TIME IEC (il preset di un TON) può contenere.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; divides by zero: on the PLC an integer division or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / 0)</extracomment>
        <translation>In %1: &apos;%2&apos; divide per zero: sul PLC una divisione intera o MOD per zero ferma il task con un guasto, e una REAL dà INF o NaN.</translation>
    </message>
    <message>
        <source>In %1: the divisor of &apos;%2&apos; can be zero: an integer division or MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / Batch)</extracomment>
        <translation>In %1: il divisore di &apos;%2&apos; può essere zero: una divisione intera o MOD per zero ferma il PLC con un guasto (e la simulazione), una REAL dà INF o NaN.</translation>
    </message>
    <message>
        <source>In %1: %2 is an edge on a variable that is not BOOL.</source>
        <extracomment>%2: an edge as written (RE Level)</extracomment>
        <translation>In %1: %2 è un fronte su una variabile che non è BOOL.</translation>
    </message>
    <message>
        <source>In %1: %2 is for receptivities only: an action cannot read an edge or a step duration.</source>
        <translation>In %1: %2 è solo per le recettività: un&apos;azione non può leggere un fronte né una durata di tappa.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is an input: it is read from the machine, actions never write it.</source>
        <translation>In %1: &apos;%2&apos; è un ingresso: è letto dalla macchina, le azioni non lo scrivono mai.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is %3; a continuous action needs a BOOL variable.</source>
        <extracomment>%3: an IEC type name (INT)</extracomment>
        <translation>In %1: &apos;%2&apos; è %3; un&apos;azione continua richiede una variabile BOOL.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is also driven by continuous actions; a variable has either continuous or stored actions (the stored one is not generated).</source>
        <translation>In %1: &apos;%2&apos; è pilotata anche da azioni continue; una variabile ha azioni continue o memorizzate (quella memorizzata non è generata).</translation>
    </message>
    <message>
        <source>In %1: invalid variable name: %2.</source>
        <translation>In %1: nome di variabile non valido: %2.</translation>
    </message>
    <message>
        <source>In %1: the condition reads &apos;%2&apos;, a continuous output of the same GRAFCET.</source>
        <translation>In %1: la condizione legge &apos;%2&apos;, un&apos;uscita continua dello stesso GRAFCET.</translation>
    </message>
    <message>
        <source>The receptivity of T%2 of %1 is empty: write TRUE for a transition that is always ready.</source>
        <translation>La recettività di T%2 di %1 è vuota: scrivete TRUE per una transizione sempre pronta.</translation>
    </message>
</context>
<context>
    <name>OperatorItem</name>
    <message>
        <source>switched on</source>
        <translation>attivato</translation>
    </message>
    <message>
        <source>switched off</source>
        <translation>disattivato</translation>
    </message>
    <message>
        <source>pressed</source>
        <translation>premuto</translation>
    </message>
    <message>
        <source>released</source>
        <translation>rilasciato</translation>
    </message>
</context>
<context>
    <name>PackMLDiagnosticText</name>
    <message>
        <source>The model has no unit mode.</source>
        <translation>Il modello non ha alcuna modalità di unità.</translation>
    </message>
    <message>
        <source>The initial mode %1 is not a unit mode of the model.</source>
        <translation>La modalità iniziale %1 non è una modalità di unità del modello.</translation>
    </message>
    <message>
        <source>The initial state %1 is not Stopped, Idle or Aborted.</source>
        <translation>Lo stato iniziale %1 non è Stopped, Idle o Aborted.</translation>
    </message>
    <message>
        <source>The model&apos;s name &apos;%1&apos; cannot name the PROGRAM (it is no IEC identifier, or the generated code or a variable takes it): the PROGRAM is named %2.</source>
        <translation>Il nome del modello «%1» non può nominare il PROGRAM (non è un identificatore IEC, oppure lo usa il codice generato o una variabile): il PROGRAM si chiama %2.</translation>
    </message>
    <message>
        <source>Unit mode %1 is outside 1..31 (PackTags UnitMode).</source>
        <translation>La modalità di unità %1 è fuori da 1..31 (PackTags UnitMode).</translation>
    </message>
    <message>
        <source>Unit mode %1 is given twice.</source>
        <translation>La modalità di unità %1 è indicata due volte.</translation>
    </message>
    <message>
        <source>Unit mode %1 is named %2, not &apos;%3&apos;.</source>
        <extracomment>%2: the fixed name of a base mode (Production, Maintenance, Manual)</extracomment>
        <translation>La modalità di unità %1 si chiama %2, non «%3».</translation>
    </message>
    <message>
        <source>The name &apos;%2&apos; of unit mode %1 is not an IEC identifier, and it becomes part of the names of function blocks.</source>
        <translation>Il nome «%2» della modalità di unità %1 non è un identificatore IEC, e diventa parte dei nomi dei blocchi funzione.</translation>
    </message>
    <message>
        <source>The name &apos;%2&apos; of unit mode %1 is one the generated code uses.</source>
        <translation>Il nome «%2» della modalità di unità %1 è usato dal codice generato.</translation>
    </message>
    <message>
        <source>Unit mode %1 is named &apos;%2&apos;, as mode %3 is (ignoring case).</source>
        <translation>La modalità di unità %1 si chiama «%2», come la modalità %3 (senza distinguere maiuscole e minuscole).</translation>
    </message>
    <message>
        <source>Mode %1 lists %2 as disabled, which every unit needs: ignored.</source>
        <translation>La modalità %1 elenca %2 come disattivato, ma ogni unità ne ha bisogno: ignorato.</translation>
    </message>
    <message>
        <source>Mode %1 lists %2 as disabled, but it stays enabled while %3 is enabled.</source>
        <extracomment>%3: the enabled acting states of the loop (Holding, Unholding)</extracomment>
        <translation>La modalità %1 elenca %2 come disattivato, ma resta attivato finché %3 è attivato.</translation>
    </message>
    <message>
        <source>Mode %1 allows a mode change in %2, an acting state, half-way through its GRAFCET: ignored.</source>
        <translation>La modalità %1 consente un cambio di modalità in %2, uno stato attivo, a metà del suo GRAFCET: ignorato.</translation>
    </message>
    <message>
        <source>Mode %1 allows a mode change in %2, which it disables: no effect.</source>
        <translation>La modalità %1 consente un cambio di modalità in %2, che disattiva: nessun effetto.</translation>
    </message>
    <message>
        <source>Mode %1 can never be current: it is not the initial mode, and no state allows a change into it from another mode.</source>
        <translation>La modalità %1 non può mai essere quella corrente: non è la modalità iniziale e nessuno stato consente di passarvi da un&apos;altra modalità.</translation>
    </message>
    <message>
        <source>In mode %1, no sequence of transitions leads to Execute from where the mode begins (counting a State Complete only where the state&apos;s GRAFCET writes Complete).</source>
        <translation>Nella modalità %1 nessuna sequenza di transizioni porta a Execute da dove la modalità inizia (uno State Complete conta solo dove il GRAFCET dello stato scrive Complete).</translation>
    </message>
    <message>
        <source>In mode %1, no sequence of transitions reaches %2 from where the mode begins: it is never active.</source>
        <translation>Nella modalità %1 nessuna sequenza di transizioni raggiunge %2 da dove la modalità inizia: non è mai attivo.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: Aborting never writes Complete: nothing leaves Aborting, so the unit can never reach Aborted.</source>
        <translation>Il GRAFCET di %1: Aborting non scrive mai Complete: nulla esce da Aborting, quindi l&apos;unità non può mai raggiungere Aborted.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: %2 never writes Complete: only Stop or Abort leave the state.</source>
        <translation>Il GRAFCET di %1: %2 non scrive mai Complete: solo Stop o Abort escono dallo stato.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: %2 is kept, but the mode disables the state: it generates no code.</source>
        <translation>Il GRAFCET di %1: %2 è conservato, ma la modalità disattiva lo stato: non genera codice.</translation>
    </message>
    <message>
        <source>there is no mode %1</source>
        <translation>non esiste la modalità %1</translation>
    </message>
    <message>
        <source>that is the mode itself</source>
        <translation>è la modalità stessa</translation>
    </message>
    <message>
        <source>mode %1 has no GRAFCET of its own there</source>
        <translation>la modalità %1 non vi ha un GRAFCET proprio</translation>
    </message>
    <message>
        <source>%1: %2 runs the same GRAFCET as mode %3, but %4.</source>
        <extracomment>%4: why (there is no mode 9, that is the mode itself, ...)</extracomment>
        <translation>%1: %2 esegue lo stesso GRAFCET della modalità %3, ma %4.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: Execute writes Complete, which nothing reads in the 2022 edition: use the Complete command.</source>
        <translation>Il GRAFCET di %1: Execute scrive Complete, che nell&apos;edizione 2022 nulla legge: usate il comando Complete.</translation>
    </message>
    <message>
        <source>The condition of %1 is empty: write FALSE for a command that comes only through CntrlCmd.</source>
        <translation>La condizione di %1 è vuota: scrivete FALSE per un comando che arriva solo tramite CntrlCmd.</translation>
    </message>
    <message>
        <source>Command %2 has the same condition as command %1: one rising edge issues both, and only the first in priority acts.</source>
        <translation>Il comando %2 ha la stessa condizione del comando %1: un solo fronte di salita li emette entrambi, e agisce solo il primo in priorità.</translation>
    </message>
    <message>
        <source>The request of mode %2 has the same condition as the request of mode %1: one rising edge issues both, and only the first in priority acts.</source>
        <translation>La richiesta della modalità %2 ha la stessa condizione della richiesta della modalità %1: un solo fronte di salita le emette entrambe, e agisce solo la prima in priorità.</translation>
    </message>
    <message>
        <source>The condition of %1 reads the output &apos;%2&apos;: commands and mode requests come from an operator, a line controller or an alarm, so read an input or an internal variable.</source>
        <translation>La condizione di %1 legge l&apos;uscita «%2»: comandi e richieste di modalità vengono da un operatore, da un controllore di linea o da un allarme, quindi leggete un ingresso o una variabile interna.</translation>
    </message>
    <message>
        <source>No enabled state of any mode accepts the command %1: it generates no code.</source>
        <translation>Nessuno stato attivato di alcuna modalità accetta il comando %1: non genera codice.</translation>
    </message>
    <message>
        <source>The Complete command exists in the 2022 edition only: its setting is ignored in this 2015 model.</source>
        <translation>Il comando Complete esiste solo nell&apos;edizione 2022: la sua impostazione è ignorata in questo modello 2015.</translation>
    </message>
    <message>
        <source>The option completeInSuspendedHeld is for the 2022 edition only: it is ignored in this 2015 model.</source>
        <translation>L&apos;opzione completeInSuspendedHeld vale solo per l&apos;edizione 2022: è ignorata in questo modello 2015.</translation>
    </message>
    <message>
        <source>a step activity</source>
        <translation>un&apos;attività di tappa</translation>
    </message>
    <message>
        <source>a step duration</source>
        <translation>una durata di tappa</translation>
    </message>
    <message>
        <source>an edge</source>
        <translation>un fronte</translation>
    </message>
    <message>
        <source>The condition of %1 uses %2 (&apos;%3&apos;), which only the texts of nested GRAFCETs have; a command or request is already the rising edge of its condition.</source>
        <extracomment>%2: what the condition uses (a step activity, an edge...); %3: the text as written</extracomment>
        <translation>La condizione di %1 usa %2 («%3»), che hanno solo i testi dei GRAFCET annidati; un comando o una richiesta è già il fronte di salita della sua condizione.</translation>
    </message>
    <message>
        <source>mode %1</source>
        <extracomment>A unit mode of a PackML model: &quot;mode Manual&quot;</extracomment>
        <translation>modalità %1</translation>
    </message>
    <message>
        <source>command %1</source>
        <extracomment>A PackML command: &quot;command Hold&quot;</extracomment>
        <translation>comando %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>A state in a unit mode: &quot;Manual: Execute&quot;</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>request of mode %1</source>
        <extracomment>The request condition of a unit mode</extracomment>
        <translation>richiesta della modalità %1</translation>
    </message>
    <message>
        <source>The variable name &apos;%1&apos; is one the generated PackML code uses (PackTags, the state machine, the function blocks or the program %2).</source>
        <translation>Il nome di variabile «%1» è usato dal codice PackML generato (PackTags, la macchina a stati, i blocchi funzione o il programma %2).</translation>
    </message>
</context>
<context>
    <name>PackmlChartExport</name>
    <message>
        <source>PackML chart drawn by GG Studio</source>
        <translation>Diagramma PackML disegnato da GG Studio</translation>
    </message>
    <message>
        <source>Unit mode %1</source>
        <translation>Modo di unità %1</translation>
    </message>
</context>
<context>
    <name>PackmlSimulationText</name>
    <message>
        <source>%1 cannot be entered in %2: %3</source>
        <extracomment>%1: a unit mode (Manual), %2: a PackML state (Execute), %3: why</extracomment>
        <translation>%1 non può essere attivato in %2: %3</translation>
    </message>
    <message>
        <source>%1; %2 grants it in no state</source>
        <extracomment>%1: a refusal, %2: the current unit mode</extracomment>
        <translation>%1; %2 non lo concede in nessuno stato</translation>
    </message>
    <message>
        <source>%1; it can be entered in %2</source>
        <extracomment>%1: a refusal, %2: PackML states (&quot;Stopped, Idle, Aborted&quot;)</extracomment>
        <translation>%1; può essere attivato in %2</translation>
    </message>
    <message>
        <source>%1 allows no mode change there</source>
        <translation>%1 non consente lì alcun cambio di modo</translation>
    </message>
    <message>
        <source>%1 disables this state</source>
        <translation>%1 disattiva questo stato</translation>
    </message>
    <message>
        <source>%1 is not granted: %2, lower-numbered, is granted in the same scan</source>
        <extracomment>%2: the unit mode granted instead</extracomment>
        <translation>%1 non è concesso: %2, di numero inferiore, è concesso nello stesso ciclo</translation>
    </message>
    <message>
        <source>%1 is requested: it is already the current mode</source>
        <translation>%1 è richiesto: è già il modo corrente</translation>
    </message>
    <message>
        <source>%1 names no unit mode</source>
        <translation>%1 non indica alcun modo dell&apos;unità</translation>
    </message>
    <message>
        <source>the SC of %1</source>
        <translation>il SC di %1</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2</source>
        <extracomment>%1: a PackML command (Hold), %2: a state (Idle)</extracomment>
        <translation>%1 non è accettato in %2</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2 in %3: the mode disables where it leads</source>
        <extracomment>%1: a command, %2: a state, %3: a unit mode</extracomment>
        <translation>%1 non è accettato in %2 in %3: il modo disattiva lo stato a cui porta</translation>
    </message>
    <message>
        <source>%1 is pre-empted by %2</source>
        <extracomment>%2: the transition that fired instead (&quot;Execute-Stop-&gt;Stopped&quot;)</extracomment>
        <translation>%1 è preceduto da %2</translation>
    </message>
    <message>
        <source>%1 names no command</source>
        <translation>%1 non indica alcun comando</translation>
    </message>
    <message>
        <source>the receptivity of T%1 of %2</source>
        <extracomment>%1: a transition number of a nested GRAFCET, %2: its function block instance</extracomment>
        <translation>la ricettività di T%1 di %2</translation>
    </message>
    <message>
        <source>action %1 of step %2 of %3</source>
        <extracomment>%1: an action&apos;s position, %2: a step number, %3: a function block instance</extracomment>
        <translation>l&apos;azione %1 del passo %2 di %3</translation>
    </message>
    <message>
        <source>the condition of the %1 command</source>
        <extracomment>%1: a PackML command (Start)</extracomment>
        <translation>la condizione del comando %1</translation>
    </message>
    <message>
        <source>the request condition of mode %1</source>
        <extracomment>%1: a unit mode (Manual)</extracomment>
        <translation>la condizione di richiesta del modo %1</translation>
    </message>
    <message>
        <source>cannot set %1: %2</source>
        <extracomment>%1: a variable or instance, %2: why (from the simulator)</extracomment>
        <translation>impossibile impostare %1: %2</translation>
    </message>
    <message>
        <source>expected state %1, the state is %2</source>
        <translation>atteso lo stato %1, lo stato è %2</translation>
    </message>
    <message>
        <source>expected mode %1, the mode is %2</source>
        <translation>atteso il modo %1, il modo è %2</translation>
    </message>
    <message>
        <source>expected %1 = %2, it is %3</source>
        <translation>atteso %1 = %2, è %3</translation>
    </message>
    <message>
        <source>expected %1 to fire, no transition fired</source>
        <translation>atteso il superamento di %1, nessuna transizione superata</translation>
    </message>
    <message>
        <source>expected %1 to fire, %2 fired</source>
        <translation>atteso il superamento di %1, superata %2</translation>
    </message>
    <message>
        <source>expected no transition to fire, %1 fired</source>
        <translation>nessun superamento atteso, superata %1</translation>
    </message>
    <message>
        <source>scan %1: %2</source>
        <extracomment>%1: a scan number, %2: what did not hold</extracomment>
        <translation>ciclo %1: %2</translation>
    </message>
    <message>
        <source>Stopped at scan %1: integer division by zero in %2 (%3 in &apos;%4&apos;). On the PLC the task stops with a fault; Reset to run again.</source>
        <extracomment>%1: a scan number, %2: where (a condition, a receptivity, an action), %3: the division as written, %4: the text</extracomment>
        <translation>Arrestato al ciclo %1: divisione intera per zero in %2 (%3 in «%4»). Nel PLC il task si ferma con un errore; reimposta per ripartire.</translation>
    </message>
    <message>
        <source>%1: granted</source>
        <extracomment>a unit mode request that the mode manager granted</extracomment>
        <translation>%1: concesso</translation>
    </message>
    <message>
        <source>%1: not granted</source>
        <translation>%1: non concesso</translation>
    </message>
    <message>
        <source>%1: fired %2</source>
        <extracomment>%1: a command, %2: the transition it fired (&quot;Idle-Start-&gt;Execute&quot;)</extracomment>
        <translation>%1: superata %2</translation>
    </message>
    <message>
        <source>%1: no transition fired</source>
        <translation>%1: nessuna transizione superata</translation>
    </message>
</context>
<context>
    <name>PackmlTexts</name>
    <message>
        <source>Wait state</source>
        <translation>Stato di attesa</translation>
    </message>
    <message>
        <source>Acting state</source>
        <translation>Stato attivo</translation>
    </message>
    <message>
        <source>Dual state: acts and waits for a command</source>
        <translation>Stato duale: agisce e attende un comando</translation>
    </message>
    <message>
        <source>Clears the faults that led to Aborted, then goes to Stopped.</source>
        <translation>Cancella i guasti che hanno portato ad Aborted, poi passa a Stopped.</translation>
    </message>
    <message>
        <source>Powered and stationary; waits for Reset.</source>
        <translation>Alimentata e ferma; attende Reset.</translation>
    </message>
    <message>
        <source>Prepares the unit to produce, then goes to Execute.</source>
        <translation>Prepara l&apos;unità a produrre, poi passa a Execute.</translation>
    </message>
    <message>
        <source>Reset and ready; waits for Start.</source>
        <translation>Ripristinata e pronta; attende Start.</translation>
    </message>
    <message>
        <source>Paused by a condition outside the unit (starved, blocked); waits for Unsuspend.</source>
        <translation>In pausa per una condizione esterna all&apos;unità (mancanza, blocco); attende Unsuspend.</translation>
    </message>
    <message>
        <source>Produces; waits for Hold, Suspend or the end of the batch.</source>
        <translation>Produce; attende Hold, Suspend o la fine del lotto.</translation>
    </message>
    <message>
        <source>Brings the unit to a controlled stop, then goes to Stopped.</source>
        <translation>Porta l&apos;unità a un arresto controllato, poi passa a Stopped.</translation>
    </message>
    <message>
        <source>Brings the unit to a quick safe stop, then goes to Aborted.</source>
        <translation>Porta l&apos;unità a un arresto rapido e sicuro, poi passa ad Aborted.</translation>
    </message>
    <message>
        <source>Stopped after an abort; waits for Clear.</source>
        <translation>Ferma dopo un&apos;interruzione; attende Clear.</translation>
    </message>
    <message>
        <source>Brings production to a controlled pause for an internal reason, then goes to Held.</source>
        <translation>Porta la produzione a una pausa controllata per una causa interna, poi passa a Held.</translation>
    </message>
    <message>
        <source>Paused for an internal reason; waits for Unhold.</source>
        <translation>In pausa per una causa interna; attende Unhold.</translation>
    </message>
    <message>
        <source>Prepares to resume production after Held, then goes to Execute.</source>
        <translation>Prepara la ripresa della produzione dopo Held, poi passa a Execute.</translation>
    </message>
    <message>
        <source>Brings production to a controlled pause for an outside reason, then goes to Suspended.</source>
        <translation>Porta la produzione a una pausa controllata per una causa esterna, poi passa a Suspended.</translation>
    </message>
    <message>
        <source>Prepares to resume production after Suspended, then goes to Execute.</source>
        <translation>Prepara la ripresa della produzione dopo Suspended, poi passa a Execute.</translation>
    </message>
    <message>
        <source>Brings the unit to its ready state, then goes to Idle.</source>
        <translation>Porta l&apos;unità nel suo stato di pronto, poi passa a Idle.</translation>
    </message>
    <message>
        <source>Ends the batch in order, then goes to Complete.</source>
        <translation>Termina il lotto in ordine, poi passa a Complete.</translation>
    </message>
    <message>
        <source>The batch is complete; waits for Reset.</source>
        <translation>Il lotto è completato; attende Reset.</translation>
    </message>
    <message>
        <source>Reset: make the unit ready to start again.</source>
        <translation>Reset: rendere l&apos;unità pronta a ripartire.</translation>
    </message>
    <message>
        <source>Start: begin producing.</source>
        <translation>Start: iniziare a produrre.</translation>
    </message>
    <message>
        <source>Stop: bring the unit to a controlled stop.</source>
        <translation>Stop: portare l&apos;unità a un arresto controllato.</translation>
    </message>
    <message>
        <source>Hold: pause production for an internal reason.</source>
        <translation>Hold: mettere in pausa la produzione per una causa interna.</translation>
    </message>
    <message>
        <source>Unhold: resume production after a Hold.</source>
        <translation>Unhold: riprendere la produzione dopo un Hold.</translation>
    </message>
    <message>
        <source>Suspend: pause production for an outside reason.</source>
        <translation>Suspend: mettere in pausa la produzione per una causa esterna.</translation>
    </message>
    <message>
        <source>Unsuspend: resume production after a Suspend.</source>
        <translation>Unsuspend: riprendere la produzione dopo un Suspend.</translation>
    </message>
    <message>
        <source>Abort: stop the unit at once, safely.</source>
        <translation>Abort: fermare l&apos;unità subito, in sicurezza.</translation>
    </message>
    <message>
        <source>Clear: clear the faults after an Abort.</source>
        <translation>Clear: cancellare i guasti dopo un Abort.</translation>
    </message>
    <message>
        <source>Complete: end the batch.</source>
        <translation>Complete: terminare il lotto.</translation>
    </message>
</context>
<context>
    <name>PackmlVerificationText</name>
    <message>
        <source>In %1, Execute, entered again from the Hold or Suspend loop, started afresh instead of resuming where it was paused.</source>
        <translation>In %1, Execute, rientrato dal ciclo Hold o Suspend, è ripartito da capo invece di riprendere da dove era stato interrotto.</translation>
    </message>
    <message>
        <source>In %1, Execute resumed where it should have started afresh from its initial situation.</source>
        <translation>In %1, Execute ha ripreso dove avrebbe dovuto ripartire dalla sua situazione iniziale.</translation>
    </message>
    <message>
        <source>In %1, Execute resumed in a situation other than the one it was paused in.</source>
        <translation>In %1, Execute ha ripreso in una situazione diversa da quella in cui era stato interrotto.</translation>
    </message>
    <message>
        <source>The verification was not exhaustive (its time or size limit, timers or numeric inputs it explores only in part): stuck states, states never active and commands never accepted were not decided, and the absence of other findings is not a proof.</source>
        <translation>La verifica non è stata esaustiva (il suo limite di tempo o di dimensione, temporizzatori o ingressi numerici che esplora solo in parte): stati bloccati, stati mai attivi e comandi mai accettati non sono stati decisi, e l&apos;assenza di altri risultati non è una prova.</translation>
    </message>
    <message>
        <source>In %1, the GRAFCET of %2 can reach a situation from which Complete never becomes TRUE: only Stop or Abort then leave %2.</source>
        <translation>In %1, il GRAFCET di %2 può raggiungere una situazione da cui Complete non diventa mai TRUE: solo Stop o Abort fanno allora uscire da %2.</translation>
    </message>
    <message>
        <source>In %1, Aborting can reach a situation from which Aborted is never reached: nothing leaves it.</source>
        <translation>In %1, Aborting può raggiungere una situazione da cui Aborted non viene mai raggiunto: nulla ne esce.</translation>
    </message>
    <message>
        <source>%2 was active at the end of a scan in %1, a mode that disables it.</source>
        <translation>%2 era attivo alla fine di un ciclo in %1, un modo che lo disabilita.</translation>
    </message>
    <message>
        <source>The mode changed from %1 in %2, a state where this change is not allowed.</source>
        <translation>Il modo è cambiato da %1 in %2, uno stato in cui questo cambio non è consentito.</translation>
    </message>
    <message>
        <source>%1 is never the current mode.</source>
        <translation>%1 non è mai il modo corrente.</translation>
    </message>
    <message>
        <source>%2 is enabled in %1 but never active there.</source>
        <translation>%2 è abilitato in %1 ma non vi è mai attivo.</translation>
    </message>
    <message>
        <source>The %1 command is accepted in no reachable configuration.</source>
        <translation>Il comando %1 non è accettato in nessuna configurazione raggiungibile.</translation>
    </message>
    <message>
        <source>In %1, continuous outputs are TRUE at the end of the scan that enters %2: %3.</source>
        <translation>In %1, uscite continue sono TRUE alla fine del ciclo che entra in %2: %3.</translation>
    </message>
    <message>
        <source>In %1, stored outputs can still be TRUE when %2 is entered: %3.</source>
        <translation>In %1, uscite memorizzate possono essere ancora TRUE all&apos;ingresso in %2: %3.</translation>
    </message>
    <message>
        <source>Stuck states were not decided in %1: timers longer than one cycle may or may not have elapsed, and the ways to Complete found there let timers elapse in an order the PLC&apos;s may not. Every other finding is decided.</source>
        <translation>Gli stati bloccati non sono stati decisi in %1: i temporizzatori più lunghi di un ciclo possono essere scaduti o no, e i percorsi verso Complete trovati lì fanno scadere i temporizzatori in un ordine che quelli del PLC possono non seguire. Tutti gli altri risultati sono decisi.</translation>
    </message>
</context>
<context>
    <name>PartSourceItem</name>
    <message>
        <source>Unlimited parts</source>
        <translation>Pezzi illimitati</translation>
    </message>
    <message>
        <source>Parts left: %1</source>
        <translation>Pezzi rimasti: %1</translation>
    </message>
    <message>
        <source>feeds no conveyor</source>
        <translation>non alimenta alcun nastro</translation>
    </message>
    <message>
        <source>feeds %1</source>
        <translation>alimenta %1</translation>
    </message>
</context>
<context>
    <name>PasteVariablesCommand</name>
    <message>
        <source>Paste variable %1</source>
        <translation>Incolla la variabile %1</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n variables</source>
        <translation>
            <numerusform>Incolla %n variabile</numerusform>
            <numerusform>Incolla %n variabili</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PictureFile</name>
    <message>
        <source>The SVG picture could not be drawn.</source>
        <translation>Impossibile disegnare l&apos;immagine SVG.</translation>
    </message>
    <message>
        <source>Not enough memory for a picture of %1 × %2 pixels.</source>
        <translation>Memoria insufficiente per un&apos;immagine di %1 × %2 pixel.</translation>
    </message>
    <message>
        <source>The PNG picture could not be encoded.</source>
        <translation>Impossibile codificare l&apos;immagine PNG.</translation>
    </message>
    <message>
        <source>The PDF document could not be drawn.</source>
        <translation>Impossibile disegnare il documento PDF.</translation>
    </message>
</context>
<context>
    <name>PropertyProblemText</name>
    <message>
        <source>&apos;%1&apos; is not a declared variable</source>
        <translation>&apos;%1&apos; non è una variabile dichiarata</translation>
    </message>
    <message>
        <source>there is no visible GEMMA step &apos;%1&apos;</source>
        <translation>non c&apos;è nessuna tappa GEMMA visibile &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the step %1 has no nested GRAFCET</source>
        <translation>la tappa %1 non ha un GRAFCET annidato</translation>
    </message>
    <message>
        <source>the GRAFCET of %1 has no step %2</source>
        <translation>il GRAFCET di %1 non ha la tappa %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is only defined when verifying with single faults (Simulation &gt; Verify with Single Faults, with the machine)</source>
        <translation>&apos;%1&apos; è definito solo verificando con guasti singoli (Simulazione &gt; Verifica con guasti singoli, con la macchina)</translation>
    </message>
</context>
<context>
    <name>RecoveryPrompt</name>
    <message>
        <source>an untitled model</source>
        <translation>un modello senza titolo</translation>
    </message>
    <message>
        <source>Discard Unsaved Changes</source>
        <translation>Scarta le modifiche non salvate</translation>
    </message>
    <message>
        <source>Delete the autosaved copy of %1 for good?</source>
        <translation>Eliminare definitivamente la copia salvata automaticamente di %1?</translation>
    </message>
    <message>
        <source>The changes it holds cannot be recovered afterwards.</source>
        <translation>Le modifiche che contiene non potranno più essere recuperate.</translation>
    </message>
    <message>
        <source>Delete Copy</source>
        <translation>Elimina la copia</translation>
    </message>
    <message>
        <source>&amp;Keep Copy</source>
        <translation>&amp;Conserva la copia</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Recupera le modifiche non salvate</translation>
    </message>
    <message>
        <source>GG Studio ended without saving %1.</source>
        <translation>GG Studio si è chiuso senza salvare %1.</translation>
    </message>
    <message>
        <source>Autosave kept a copy on %1. Recover it? You can then save it or discard it.</source>
        <translation>Il salvataggio automatico ha conservato una copia il %1. Recuperarla? Potrai poi salvarla o scartarla.</translation>
    </message>
    <message>
        <source>The original file can no longer be identified (moved, deleted or changed since, or named by an older version): saving the recovered model will ask for a file.</source>
        <translation>Il file originale non è più identificabile (spostato, eliminato o modificato nel frattempo, oppure indicato da una versione precedente): al salvataggio del modello recuperato verrà chiesto un file.</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Recupera</translation>
    </message>
    <message>
        <source>Discard…</source>
        <translation>Scarta…</translation>
    </message>
    <message>
        <source>&amp;Not Now</source>
        <translation>&amp;Non ora</translation>
    </message>
    <message>
        <source>The autosaved copy could not be read.</source>
        <translation>Impossibile leggere la copia salvata automaticamente.</translation>
    </message>
</context>
<context>
    <name>RemoveGrafcetActionCommand</name>
    <message>
        <source>Remove action %1 of %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Rimuovi l’azione %1 della tappa %3 di %2</translation>
    </message>
</context>
<context>
    <name>RemoveMachineComponentCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>Rimuovi %1</translation>
    </message>
</context>
<context>
    <name>RemoveModeCommand</name>
    <message>
        <source>Remove mode %1</source>
        <translation>Rimuovi il modo %1</translation>
    </message>
</context>
<context>
    <name>RemovePropertyCommand</name>
    <message>
        <source>Remove property %1</source>
        <translation>Rimuovi la proprietà %1</translation>
    </message>
</context>
<context>
    <name>RemoveVariableCommand</name>
    <message>
        <source>Remove variable %1</source>
        <translation>Rimuovi la variabile %1</translation>
    </message>
</context>
<context>
    <name>RenameModeCommand</name>
    <message>
        <source>Rename mode %1</source>
        <translation>Rinomina il modo %1</translation>
    </message>
</context>
<context>
    <name>RenameVariableCommand</name>
    <message>
        <source>Rename variable %1 to %2</source>
        <translation>Rinomina la variabile %1 in %2</translation>
    </message>
    <message>
        <source>a variable named &apos;%1&apos; already exists (IEC names ignore case)</source>
        <translation>esiste già una variabile di nome &apos;%1&apos; (i nomi IEC non distinguono maiuscole e minuscole)</translation>
    </message>
</context>
<context>
    <name>RenumberGrafcetStepCommand</name>
    <message>
        <source>Renumber %1 step %2 to %3</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET, %3 its new number</extracomment>
        <translation>Rinumera la tappa %2 di %1 in %3</translation>
    </message>
</context>
<context>
    <name>ResetModelCommand</name>
    <message>
        <source>Reset to template</source>
        <translation>Ripristina il template</translation>
    </message>
</context>
<context>
    <name>SetCommandCommentCommand</name>
    <message>
        <source>Edit comment of command %1</source>
        <translation>Modifica il commento del comando %1</translation>
    </message>
</context>
<context>
    <name>SetCommandConditionCommand</name>
    <message>
        <source>Edit condition of command %1</source>
        <translation>Modifica la condizione del comando %1</translation>
    </message>
</context>
<context>
    <name>SetConditionCommand</name>
    <message>
        <source>Edit condition of %1</source>
        <translation>Modifica la condizione di %1</translation>
    </message>
</context>
<context>
    <name>SetCycleTimeCommand</name>
    <message>
        <source>Set cycle time to %1 ms</source>
        <translation>Imposta il tempo di ciclo a %1 ms</translation>
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
        <translation>Imposta il dialetto a %1</translation>
    </message>
</context>
<context>
    <name>SetElementsHiddenCommand</name>
    <message numerus="yes">
        <source>Hide %n element(s)</source>
        <translation>
            <numerusform>Nascondi %n elemento</numerusform>
            <numerusform>Nascondi %n elementi</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show %n element(s)</source>
        <translation>
            <numerusform>Mostra %n elemento</numerusform>
            <numerusform>Mostra %n elementi</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SetEvolutionRuleCommand</name>
    <message>
        <source>Set evolution rule to until stable</source>
        <translation>Imposta la regola di evoluzione a «fino alla stabilità»</translation>
    </message>
    <message>
        <source>Set evolution rule to one evolution per scan</source>
        <translation>Imposta la regola di evoluzione a «un&apos;evoluzione per ciclo»</translation>
    </message>
</context>
<context>
    <name>SetGrafcetActionCommand</name>
    <message>
        <source>Set action %1 of %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Modifica l’azione %1 della tappa %3 di %2</translation>
    </message>
</context>
<context>
    <name>SetGrafcetChoiceCommand</name>
    <message>
        <source>Give %1 its own GRAFCET in mode %2</source>
        <translation>Dare a %1 un proprio GRAFCET nel modo %2</translation>
    </message>
    <message>
        <source>Run in %1 of mode %2 the GRAFCET of mode %3</source>
        <translation>Eseguire in %1 del modo %2 il GRAFCET del modo %3</translation>
    </message>
    <message>
        <source>Remove the GRAFCET of %1 in mode %2</source>
        <translation>Rimuovi il GRAFCET di %1 nel modo %2</translation>
    </message>
</context>
<context>
    <name>SetGrafcetStepCommentCommand</name>
    <message>
        <source>Edit comment of %1 step %2</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET: &quot;Edit comment of F1 step 3&quot;</extracomment>
        <translation>Modifica il commento della tappa %2 di %1</translation>
    </message>
</context>
<context>
    <name>SetGrafcetStepInitialCommand</name>
    <message>
        <source>Make %1 step %2 initial</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET</extracomment>
        <translation>Rendi iniziale la tappa %2 di %1</translation>
    </message>
    <message>
        <source>Make %1 step %2 not initial</source>
        <translation>Rendi non iniziale la tappa %2 di %1</translation>
    </message>
</context>
<context>
    <name>SetInitialStepCommand</name>
    <message>
        <source>Make %1 the initial step</source>
        <translation>Rendi %1 la tappa iniziale</translation>
    </message>
</context>
<context>
    <name>SetModeCommentCommand</name>
    <message>
        <source>Edit comment of mode %1</source>
        <translation>Modifica il commento del modo %1</translation>
    </message>
</context>
<context>
    <name>SetModeRequestCommand</name>
    <message>
        <source>Edit request condition of mode %1</source>
        <translation>Modifica la condizione di richiesta del modo %1</translation>
    </message>
</context>
<context>
    <name>SetModeStatesCommand</name>
    <message>
        <source>Change disabled states of mode %1</source>
        <translation>Modifica gli stati disattivati del modo %1</translation>
    </message>
    <message>
        <source>Change mode-change states of mode %1</source>
        <translation>Modifica gli stati di cambio modo del modo %1</translation>
    </message>
</context>
<context>
    <name>SetModelNameCommand</name>
    <message>
        <source>Rename model</source>
        <translation>Rinomina il modello</translation>
    </message>
</context>
<context>
    <name>SetNegatedCommand</name>
    <message>
        <source>Negate %1</source>
        <translation>Nega %1</translation>
    </message>
    <message>
        <source>Remove negation of %1</source>
        <translation>Rimuovi la negazione di %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlInitialModeCommand</name>
    <message>
        <source>Set initial mode to %1</source>
        <translation>Imposta il modo iniziale a %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlInitialStateCommand</name>
    <message>
        <source>Set initial state to %1</source>
        <translation>Imposta lo stato iniziale a %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlOptionsCommand</name>
    <message>
        <source>Change PackML edition and options</source>
        <translation>Modifica edizione e opzioni PackML</translation>
    </message>
</context>
<context>
    <name>SetPriorityCommand</name>
    <message>
        <source>Set priority of %1 to %2</source>
        <translation>Imposta la priorità di %1 a %2</translation>
    </message>
</context>
<context>
    <name>SetPropertyCommentCommand</name>
    <message>
        <source>Edit comment of property %1</source>
        <translation>Modifica il commento della proprietà %1</translation>
    </message>
</context>
<context>
    <name>SetPropertyTextCommand</name>
    <message>
        <source>Edit property %1</source>
        <translation>Modifica la proprietà %1</translation>
    </message>
</context>
<context>
    <name>SetReceptivityCommand</name>
    <message>
        <source>Set receptivity of %1 T%2</source>
        <extracomment>%1 is the GEMMA step, %2 the transition number of its nested GRAFCET: &quot;Set receptivity of F1 T3&quot;</extracomment>
        <translation>Modifica la ricettività di %1 T%2</translation>
    </message>
</context>
<context>
    <name>SetStepCommentCommand</name>
    <message>
        <source>Edit comment of %1</source>
        <translation>Modifica il commento di %1</translation>
    </message>
</context>
<context>
    <name>SetStepHiddenCommand</name>
    <message>
        <source>Hide step %1</source>
        <translation>Nascondi la tappa %1</translation>
    </message>
    <message>
        <source>Show step %1</source>
        <translation>Mostra la tappa %1</translation>
    </message>
</context>
<context>
    <name>SetStepTypeCommand</name>
    <message>
        <source>macro-step</source>
        <translation>macro-tappa</translation>
    </message>
    <message>
        <source>enclosing step</source>
        <translation>tappa incapsulante</translation>
    </message>
    <message>
        <source>simple step</source>
        <translation>tappa semplice</translation>
    </message>
    <message>
        <source>Set %1 to %2</source>
        <translation>Imposta %1 come %2</translation>
    </message>
</context>
<context>
    <name>SetTokensCommand</name>
    <message>
        <source>Set tokens of %1</source>
        <translation>Imposta le memorie di %1</translation>
    </message>
</context>
<context>
    <name>SetTransitionHiddenCommand</name>
    <message>
        <source>Hide transition %1</source>
        <translation>Nascondi la transizione %1</translation>
    </message>
    <message>
        <source>Show transition %1</source>
        <translation>Mostra la transizione %1</translation>
    </message>
</context>
<context>
    <name>SetVariableCommentCommand</name>
    <message>
        <source>Edit comment of %1</source>
        <translation>Modifica il commento di %1</translation>
    </message>
</context>
<context>
    <name>SetVariableDefaultCommand</name>
    <message>
        <source>Set default of %1</source>
        <translation>Imposta il valore iniziale di %1</translation>
    </message>
</context>
<context>
    <name>SetVariableKindCommand</name>
    <message>
        <source>Set kind of %1 to output</source>
        <translation>Imposta la natura di %1 a uscita</translation>
    </message>
    <message>
        <source>Set kind of %1 to internal</source>
        <translation>Imposta la natura di %1 a interna</translation>
    </message>
    <message>
        <source>Set kind of %1 to input</source>
        <translation>Imposta la natura di %1 a ingresso</translation>
    </message>
</context>
<context>
    <name>SetVariableTypeCommand</name>
    <message>
        <source>Set type of %1 to %2</source>
        <translation>Imposta il tipo di %1 a %2</translation>
    </message>
</context>
<context>
    <name>SimulationText</name>
    <message>
        <source>%1 = %2 (token of %3)</source>
        <extracomment>a token variable, its value, then the literal it stores (&quot;NOT Stop&quot;)</extracomment>
        <translation>%1 = %2 (memoria di %3)</translation>
    </message>
    <message>
        <source>%1 is %2</source>
        <extracomment>an IEC expression of a condition, then TRUE or FALSE</extracomment>
        <translation>%1 è %2</translation>
    </message>
    <message>
        <source>%1 is %2 (%3)</source>
        <extracomment>an IEC expression of a condition, TRUE or FALSE, then the values it reads (&quot;Speed = 3&quot;)</extracomment>
        <translation>%1 è %2 (%3)</translation>
    </message>
    <message>
        <source>The condition cannot be used: it is FALSE.</source>
        <translation>La condizione non è utilizzabile: vale FALSE.</translation>
    </message>
    <message>
        <source>cannot apply: %1</source>
        <extracomment>%1: why, from the simulator (English)</extracomment>
        <translation>impossibile applicare: %1</translation>
    </message>
    <message>
        <source>expected step %1, active step is %2</source>
        <translation>attesa la tappa %1, la tappa attiva è %2</translation>
    </message>
    <message>
        <source>expected step %1, no visible step is active (State = %2)</source>
        <translation>attesa la tappa %1, nessuna tappa visibile è attiva (State = %2)</translation>
    </message>
    <message>
        <source>expected %1 to fire, no transition fired</source>
        <translation>%1 doveva scattare, nessuna transizione è scattata</translation>
    </message>
    <message>
        <source>expected %1 to fire, %2 fired</source>
        <translation>%1 doveva scattare, è scattata %2</translation>
    </message>
    <message>
        <source>expected no transition to fire, %1 fired</source>
        <translation>nessuna transizione doveva scattare, è scattata %1</translation>
    </message>
    <message>
        <source>expected token %1 = %2, it is %3</source>
        <translation>attesa la memoria %1 = %2, vale %3</translation>
    </message>
    <message>
        <source>expected %1 = %2, it is %3</source>
        <extracomment>a variable, the value expected, the value it has</extracomment>
        <translation>atteso %1 = %2, vale %3</translation>
    </message>
    <message>
        <source>unknown variable &apos;%1&apos;</source>
        <translation>variabile &apos;%1&apos; sconosciuta</translation>
    </message>
    <message>
        <source>expected Entry = %1, it is %2</source>
        <translation>atteso Entry = %1, vale %2</translation>
    </message>
    <message>
        <source>expected %1.Complete = %2, it is %3</source>
        <translation>atteso %1.Complete = %2, vale %3</translation>
    </message>
    <message>
        <source>%1.Complete = FALSE</source>
        <extracomment>a macro-step or enclosing step; the transition waits for its Complete</extracomment>
        <translation>%1.Complete = FALSE</translation>
    </message>
    <message>
        <source>%1 fires first</source>
        <extracomment>a transition of higher priority whose condition holds</extracomment>
        <translation>%1 scatta per prima</translation>
    </message>
    <message>
        <source>scan %1: %2</source>
        <extracomment>a scan number, then what differed</extracomment>
        <translation>ciclo %1: %2</translation>
    </message>
    <message>
        <source>expected &apos;at SCAN:&apos; at the start of the line, found %1</source>
        <extracomment>%1: the word found in quotes, or &quot;the end of the line&quot;; &apos;at SCAN:&apos; is scenario syntax</extracomment>
        <translation>atteso &apos;at SCAN:&apos; all&apos;inizio della riga, trovato %1</translation>
    </message>
    <message>
        <source>expected a scan number after &apos;at&apos;, found %1</source>
        <translation>atteso un numero di ciclo dopo &apos;at&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected &apos;:&apos; after the scan number, found %1</source>
        <translation>atteso &apos;:&apos; dopo il numero di ciclo, trovato %1</translation>
    </message>
    <message>
        <source>expected &apos;set&apos; or &apos;expect&apos;, found %1</source>
        <translation>atteso &apos;set&apos; o &apos;expect&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a variable name or &apos;complete STEP&apos;, found %1</source>
        <translation>atteso un nome di variabile o &apos;complete STEP&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;complete&apos;, found %1</source>
        <translation>atteso un identificativo di tappa dopo &apos;complete&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;step&apos;, found %1</source>
        <translation>atteso un identificativo di tappa dopo &apos;step&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a transition id or &apos;none&apos; after &apos;fired&apos;, found %1</source>
        <translation>atteso un identificativo di transizione o &apos;none&apos; dopo &apos;fired&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a token name after &apos;token&apos;, found %1</source>
        <translation>atteso un nome di memoria dopo &apos;token&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a variable name after &apos;variable&apos;, found %1</source>
        <translation>atteso un nome di variabile dopo &apos;variable&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the step id, found %1</source>
        <translation>atteso &apos;=&apos; dopo l&apos;identificativo di tappa, trovato %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the variable name, found %1</source>
        <translation>atteso &apos;=&apos; dopo il nome di variabile, trovato %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the token name, found %1</source>
        <translation>atteso &apos;=&apos; dopo il nome di memoria, trovato %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after &apos;entry&apos;, found %1</source>
        <translation>atteso &apos;=&apos; dopo &apos;entry&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a value after &apos;=&apos;, found %1</source>
        <translation>atteso un valore dopo &apos;=&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected TRUE or FALSE, found %1</source>
        <translation>atteso TRUE o FALSE, trovato %1</translation>
    </message>
    <message>
        <source>expected TRUE, FALSE or auto, found %1</source>
        <extracomment>auto is scenario syntax</extracomment>
        <translation>atteso TRUE, FALSE o auto, trovato %1</translation>
    </message>
    <message>
        <source>expected &apos;,&apos; or the end of the line, found %1</source>
        <translation>atteso &apos;,&apos; o la fine della riga, trovato %1</translation>
    </message>
    <message>
        <source>expected the end of the line, found %1</source>
        <translation>attesa la fine della riga, trovato %1</translation>
    </message>
    <message>
        <source>scans are numbered from 1</source>
        <translation>i cicli sono numerati a partire da 1</translation>
    </message>
    <message>
        <source>%1 is %2: %3</source>
        <extracomment>a variable, its IEC type (INT), then why the value does not fit it</extracomment>
        <translation>%1 è di tipo %2: %3</translation>
    </message>
    <message>
        <source>step %1 is hidden: it does not exist for the simulator</source>
        <translation>la tappa %1 è nascosta: non esiste per il simulatore</translation>
    </message>
    <message>
        <source>unknown step &apos;%1&apos;</source>
        <translation>tappa &apos;%1&apos; sconosciuta</translation>
    </message>
    <message>
        <source>step %1 is a simple step: it has no Complete</source>
        <translation>la tappa %1 è una tappa semplice: non ha Complete</translation>
    </message>
    <message>
        <source>transition %1 is not effective (it or one of its steps is hidden)</source>
        <translation>la transizione %1 non è effettiva (essa o una delle sue tappe è nascosta)</translation>
    </message>
    <message>
        <source>unknown transition &apos;%1&apos;</source>
        <translation>transizione &apos;%1&apos; sconosciuta</translation>
    </message>
    <message>
        <source>unknown token &apos;%1&apos;</source>
        <translation>memoria &apos;%1&apos; sconosciuta</translation>
    </message>
    <message>
        <source>the end of the line</source>
        <translation>la fine della riga</translation>
    </message>
    <message>
        <source>invalid UTF-8: a scenario file must be UTF-8 text</source>
        <translation>UTF-8 non valido: un file di scenario deve essere testo UTF-8</translation>
    </message>
    <message>
        <source>%1&apos;s Complete is set to two values in scan %2: %3 on line %4, %5 on line %6</source>
        <extracomment>a step id, a scan number, then each value with the line that sets it</extracomment>
        <translation>il Complete di %1 riceve due valori nel ciclo %2: %3 alla riga %4, %5 alla riga %6</translation>
    </message>
    <message>
        <source>%1 is set to two values in scan %2: %3 on line %4, %5 on line %6</source>
        <extracomment>a variable, a scan number, then each value with the line that sets it</extracomment>
        <translation>%1 riceve due valori nel ciclo %2: %3 alla riga %4, %5 alla riga %6</translation>
    </message>
    <message>
        <source>expected the active steps of %1 to be %2, they are %3</source>
        <extracomment>%1: a GEMMA step; %2, %3: lists of nested step numbers</extracomment>
        <translation>attese le tappe attive %2 in %1, sono %3</translation>
    </message>
    <message>
        <source>expected %1.Unstable = %2, it is %3</source>
        <translation>atteso %1.Unstable = %2, vale %3</translation>
    </message>
    <message>
        <source>expected step, fired, token, variable, entry, complete or nested after &apos;expect&apos;, found %1</source>
        <extracomment>step, fired, token, variable, entry and complete are scenario syntax</extracomment>
        <translation>atteso step, fired, token, variable, entry, complete o nested dopo «expect», trovato %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;nested&apos;, found %1</source>
        <translation>atteso un identificatore di tappa dopo «nested», trovato %1</translation>
    </message>
    <message>
        <source>expected &apos;steps&apos; or &apos;unstable&apos; after the step id, found %1</source>
        <extracomment>steps and unstable are scenario syntax</extracomment>
        <translation>atteso «steps» o «unstable» dopo l&apos;identificatore di tappa, trovato %1</translation>
    </message>
    <message>
        <source>expected a step number, found %1</source>
        <translation>atteso un numero di tappa, trovato %1</translation>
    </message>
    <message>
        <source>%1 is an output variable: the program writes it, a scenario sets only inputs</source>
        <translation>%1 è una variabile di uscita: il programma la scrive, uno scenario imposta solo ingressi</translation>
    </message>
    <message>
        <source>%1 is an internal variable: the program writes it, a scenario sets only inputs</source>
        <translation>%1 è una variabile interna: il programma la scrive, uno scenario imposta solo ingressi</translation>
    </message>
    <message>
        <source>step %1 has no nested GRAFCET</source>
        <translation>la tappa %1 non ha GRAFCET annidato</translation>
    </message>
    <message>
        <source>the Complete of %1 comes from its nested GRAFCET: it cannot be set</source>
        <translation>il Complete di %1 viene dal suo GRAFCET annidato: non può essere impostato</translation>
    </message>
    <message>
        <source>step %1 is not active</source>
        <extracomment>an upstream step of a nested GRAFCET&apos;s transition</extracomment>
        <translation>la tappa %1 non è attiva</translation>
    </message>
    <message>
        <source>steps %1 are not active</source>
        <extracomment>the upstream steps of a nested GRAFCET&apos;s transition (&quot;2, 3&quot;)</extracomment>
        <translation>le tappe %1 non sono attive</translation>
    </message>
    <message>
        <source>no rising edge of %1 this scan (%1 = %2, at the end of the previous scan %3)</source>
        <extracomment>%1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan</extracomment>
        <translation>nessun fronte di salita di %1 in questo ciclo (%1 = %2, alla fine del ciclo precedente %3)</translation>
    </message>
    <message>
        <source>no falling edge of %1 this scan (%1 = %2, at the end of the previous scan %3)</source>
        <extracomment>%1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan</extracomment>
        <translation>nessun fronte di discesa di %1 in questo ciclo (%1 = %2, alla fine del ciclo precedente %3)</translation>
    </message>
    <message>
        <source>%1 is FALSE: step %2 active for %3 ms of %4 ms</source>
        <extracomment>%1: a time-dependent receptivity (&quot;5s/X2&quot;); %2: its step; %3 of %4: elapsed and set time in ms</extracomment>
        <translation>%1 è FALSE: tappa %2 attiva da %3 ms su %4 ms</translation>
    </message>
    <message>
        <source>%1 is not the active step: its GRAFCET does not evolve in the next scan</source>
        <extracomment>a macro-step or enclosing step</extracomment>
        <translation>%1 non è la tappa attiva: il suo GRAFCET non evolve al prossimo ciclo</translation>
    </message>
    <message>
        <source>scan number %1 is too large: a scenario runs at most %2 scans</source>
        <extracomment>%2: the highest scan number a scenario may name</extracomment>
        <translation>il numero di ciclo %1 è troppo grande: uno scenario dura al massimo %2 cicli</translation>
    </message>
    <message>
        <source>expected a command name after &apos;command&apos;, found %1</source>
        <extracomment>&apos;command&apos; is scenario syntax</extracomment>
        <translation>atteso un nome di comando dopo &apos;command&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a mode name or number after &apos;mode&apos;, found %1</source>
        <extracomment>&apos;mode&apos; is scenario syntax</extracomment>
        <translation>atteso un nome o un numero di modo dopo &apos;mode&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected a state name after &apos;state&apos;, found %1</source>
        <extracomment>&apos;state&apos; is scenario syntax</extracomment>
        <translation>atteso un nome di stato dopo &apos;state&apos;, trovato %1</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;</source>
        <translation>comando sconosciuto &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown unit mode &apos;%1&apos;</source>
        <translation>modo dell&apos;unità sconosciuto &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown state &apos;%1&apos;</source>
        <translation>stato sconosciuto &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown instance &apos;%1&apos;</source>
        <extracomment>%1: a PackML function block instance (Production_Resetting)</extracomment>
        <translation>istanza sconosciuta &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is for PackML models only</source>
        <extracomment>%1: scenario syntax (&quot;command&quot;, &quot;expect state&quot;)</extracomment>
        <translation>&apos;%1&apos; vale solo per i modelli PackML</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is for GEMMA models only</source>
        <extracomment>%1: scenario syntax (&quot;expect step&quot;, &quot;set complete&quot;)</extracomment>
        <translation>&apos;%1&apos; vale solo per i modelli GEMMA</translation>
    </message>
    <message>
        <source>a %1 in scan %2 right after the one of line %3 is not seen: the request must be FALSE for one scan in between</source>
        <extracomment>%1: &quot;command&quot; or &quot;mode&quot; (scenario syntax); %2: a scan number; %3: a line number</extracomment>
        <translation>un %1 nel ciclo %2 subito dopo quello della riga %3 non viene visto: la richiesta deve restare FALSE per un ciclo nel mezzo</translation>
    </message>
    <message>
        <source>%1 is a sensor of the machine&apos;s %2: the machine sets it; set it by hand in open loop only</source>
        <extracomment>%1: a variable; %2: the name of a component of the virtual machine (&quot;Clamp&quot;)</extracomment>
        <translation>%1 è un sensore del componente %2 della macchina: la macchina lo imposta; impostarlo a mano solo in anello aperto</translation>
    </message>
    <message>
        <source>expected a sensor or component name after &apos;fault&apos;, found %1</source>
        <extracomment>&apos;fault&apos; is scenario syntax</extracomment>
        <translation>atteso un nome di sensore o di componente dopo &apos;fault&apos;, trovato %1</translation>
    </message>
    <message>
        <source>expected stuck, flicker, jam or clear after the name, found %1</source>
        <extracomment>stuck, flicker, jam and clear are scenario syntax</extracomment>
        <translation>atteso stuck, flicker, jam o clear dopo il nome, trovato %1</translation>
    </message>
    <message>
        <source>a fault needs the virtual machine: run the scenario in closed loop, on a model with a machine</source>
        <translation>un guasto richiede la macchina virtuale: esegui lo scenario ad anello chiuso, su un modello con una macchina</translation>
    </message>
    <message>
        <source>%1 is an operator input of the machine&apos;s %2: the user drives it with set; a fault applies to the machine&apos;s sensors</source>
        <extracomment>%1: a variable; %2: the name of a component of the virtual machine (&quot;Start&quot;); &apos;set&apos; is scenario syntax</extracomment>
        <translation>%1 è un ingresso operatore di %2 della macchina: l&apos;utente lo comanda con set; un guasto si applica ai sensori della macchina</translation>
    </message>
    <message>
        <source>%1 is no sensor of the machine: a fault applies to the inputs a component writes</source>
        <translation>%1 non è un sensore della macchina: un guasto si applica agli ingressi scritti da un componente</translation>
    </message>
    <message>
        <source>no component &apos;%1&apos; in the machine</source>
        <translation>nessun componente &apos;%1&apos; nella macchina</translation>
    </message>
    <message>
        <source>%1 is a %2: only cylinders and conveyors jam</source>
        <extracomment>%1: a component of the virtual machine; %2: its kind as the file spells it (&quot;lamp&quot;, &quot;push-button&quot;)</extracomment>
        <translation>%1 è di tipo %2: solo i cilindri e i nastri trasportatori si bloccano</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is neither a sensor nor a component of the machine</source>
        <translation>&apos;%1&apos; non è né un sensore né un componente della macchina</translation>
    </message>
</context>
<context>
    <name>SpecificationExport</name>
    <message>
        <source>%1 specification</source>
        <extracomment>the specification&apos;s title and the file name it is saved under; %1 is the model&apos;s name</extracomment>
        <translation>Specifica %1</translation>
    </message>
    <message>
        <source>GEMMA chart</source>
        <translation>Diagramma GEMMA</translation>
    </message>
    <message>
        <source>States</source>
        <translation>Stati</translation>
    </message>
    <message>
        <source>Transitions</source>
        <translation>Transizioni</translation>
    </message>
    <message>
        <source>Variables</source>
        <translation>Variabili</translation>
    </message>
    <message>
        <source>Nested GRAFCETs</source>
        <translation>GRAFCET annidati</translation>
    </message>
    <message>
        <source>Generated code</source>
        <translation>Codice generato</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Specifica</translation>
    </message>
    <message>
        <source>GEMMA-GRAFCET specification</source>
        <translation>Specifica GEMMA-GRAFCET</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n errore</numerusform>
            <numerusform>%n errori</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n avviso</numerusform>
            <numerusform>%n avvisi</numerusform>
        </translation>
    </message>
    <message>
        <source>File</source>
        <translation>File</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>non ancora salvato</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Data</translation>
    </message>
    <message>
        <source>Initial state</source>
        <translation>Stato iniziale</translation>
    </message>
    <message>
        <source>PLC task cycle</source>
        <translation>Ciclo del task PLC</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Code dialect</source>
        <translation>Dialetto del codice</translation>
    </message>
    <message>
        <source>Nested GRAFCET evolution</source>
        <translation>Evoluzione dei GRAFCET annidati</translation>
    </message>
    <message>
        <source>Until stable, in one call of its function block</source>
        <translation>Fino alla stabilità, in una chiamata del suo blocco funzione</translation>
    </message>
    <message>
        <source>One evolution per PLC scan</source>
        <translation>Un&apos;evoluzione per ciclo PLC</translation>
    </message>
    <message>
        <source>Checks</source>
        <translation>Controlli</translation>
    </message>
    <message>
        <source>No problems found</source>
        <translation>Nessun problema trovato</translation>
    </message>
    <message>
        <source>Written by</source>
        <translation>Scritto con</translation>
    </message>
    <message>
        <source>GG Studio %1</source>
        <translation>GG Studio %1</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>Indice</translation>
    </message>
    <message>
        <source>GEMMA chart, continued</source>
        <translation>Diagramma GEMMA, continuazione</translation>
    </message>
    <message>
        <source>States, transitions and variables</source>
        <translation>Stati, transizioni e variabili</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Stato</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>GRAFCET</source>
        <translation>GRAFCET</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Commento</translation>
    </message>
    <message>
        <source>%1, initial</source>
        <translation>%1, iniziale</translation>
    </message>
    <message numerus="yes">
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n tappa</numerusform>
            <numerusform>%n tappe</numerusform>
        </translation>
    </message>
    <message>
        <source>The visible states of the GEMMA chart, in state order. A macro-step or an enclosing step runs its nested GRAFCET while it is active.</source>
        <translation>Gli stati visibili del diagramma GEMMA, nell&apos;ordine degli stati. Una macro-tappa o una tappa incapsulante esegue il suo GRAFCET annidato finché è attiva.</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transizione</translation>
    </message>
    <message>
        <source>Priority</source>
        <translation>Priorità</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Condizione</translation>
    </message>
    <message>
        <source>Tokens</source>
        <translation>Memorie</translation>
    </message>
    <message>
        <source>%1, negated</source>
        <translation>%1, negata</translation>
    </message>
    <message>
        <source>The transitions that take part: visible, between visible states. A state evaluates its transitions by priority, 1 first; a negated transition fires when its condition is FALSE.</source>
        <translation>Le transizioni che contano: visibili, tra stati visibili. Uno stato valuta le sue transizioni per priorità, prima la 1; una transizione negata scatta quando la sua condizione è FALSE.</translation>
    </message>
    <message>
        <source>No transition takes part.</source>
        <translation>Nessuna transizione conta.</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Natura</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Valore iniziale</translation>
    </message>
    <message>
        <source>The declared variables, in declaration order. Inputs are read from the machine, outputs written by the actions of the nested GRAFCETs, internal variables are the program&apos;s memory. A variable without a default starts at its type&apos;s (FALSE, 0).</source>
        <translation>Le variabili dichiarate, nell&apos;ordine di dichiarazione. Gli ingressi sono letti dalla macchina, le uscite scritte dalle azioni dei GRAFCET annidati, le variabili interne sono la memoria del programma. Una variabile senza valore iniziale parte da quello del suo tipo (FALSE, 0).</translation>
    </message>
    <message>
        <source>No variables are declared.</source>
        <translation>Nessuna variabile è dichiarata.</translation>
    </message>
    <message numerus="yes">
        <source>%n transition(s)</source>
        <translation>
            <numerusform>%n transizione</numerusform>
            <numerusform>%n transizioni</numerusform>
        </translation>
    </message>
    <message>
        <source>function block %1</source>
        <translation>blocco funzione %1</translation>
    </message>
    <message>
        <source>This GRAFCET has no steps yet.</source>
        <translation>Questo GRAFCET non ha ancora tappe.</translation>
    </message>
    <message>
        <source>Nested GRAFCET of %1, continued</source>
        <translation>GRAFCET annidato di %1, continuazione</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Tappa</translation>
    </message>
    <message>
        <source>Steps of %1</source>
        <translation>Tappe di %1</translation>
    </message>
    <message>
        <source>GG Studio generates the PLC program as IEC 61131-3 Structured Text by the Hierarchical Design Pattern: the program %1 holds the active GEMMA state and evaluates its transitions by priority, and each visible macro-step or enclosing step is a function block that %1 calls while that state is active. This outline gives the program organisation units and their interfaces; File &gt; Export Structured Text and Export PLCopen XML write the code itself.</source>
        <translation>GG Studio genera il programma PLC in Structured Text IEC 61131-3 secondo l&apos;Hierarchical Design Pattern: il programma %1 tiene lo stato GEMMA attivo e ne valuta le transizioni per priorità, e ogni macro-tappa o tappa incapsulante visibile è un blocco funzione che %1 chiama finché quello stato è attivo. Questo schema riporta le unità di organizzazione del programma e le loro interfacce; File &gt; Esporta Testo strutturato (ST) ed Esporta PLCopen XML scrivono il codice stesso.</translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s): the generated code marks each one with a comment.</source>
        <translation>
            <numerusform>Il modello ha %n errore: il codice generato lo segnala con un commento.</numerusform>
            <numerusform>Il modello ha %n errori: il codice generato segnala ciascuno con un commento.</numerusform>
        </translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configurazione</translation>
    </message>
    <message>
        <source>Resource</source>
        <translation>Risorsa</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Task</translation>
    </message>
    <message>
        <source>%1: cyclic, every %2, priority %3</source>
        <translation>%1: ciclico, ogni %2, priorità %3</translation>
    </message>
    <message>
        <source>Program instance</source>
        <translation>Istanza del programma</translation>
    </message>
    <message>
        <source>Global variable list</source>
        <translation>Lista delle variabili globali</translation>
    </message>
    <message>
        <source>The GEMMA layer: it holds the active state in State, evaluates that state&apos;s transitions by priority and calls the function block of a state with nested behaviour while that state is active.</source>
        <translation>Il livello GEMMA: tiene lo stato attivo in State, valuta le transizioni di quello stato per priorità e chiama il blocco funzione di uno stato con comportamento annidato finché quello stato è attivo.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 (page %2). %3 calls it through its instance %4 while %4 is active.</source>
        <translation>Il GRAFCET annidato di %1 (pagina %2). %3 lo chiama tramite la sua istanza %4 finché %4 è attiva.</translation>
    </message>
    <message>
        <source>The nested behaviour of %1, not written yet: until it is, the function block completes at once. %2 calls it through its instance %3.</source>
        <translation>Il comportamento annidato di %1, non ancora scritto: nel frattempo il blocco funzione termina subito. %2 lo chiama tramite la sua istanza %3.</translation>
    </message>
    <message>
        <source>Declaration</source>
        <translation>Dichiarazione</translation>
    </message>
    <message>
        <source>Initial value</source>
        <translation>Valore iniziale</translation>
    </message>
    <message>
        <source>Global variables it reads (VAR_EXTERNAL): %1.</source>
        <translation>Variabili globali che legge (VAR_EXTERNAL): %1.</translation>
    </message>
    <message>
        <source>Its own variables (VAR): %1.</source>
        <translation>Le sue variabili (VAR): %1.</translation>
    </message>
    <message>
        <source>Global variables</source>
        <translation>Variabili globali</translation>
    </message>
    <message>
        <source>in the VAR_GLOBAL of the configuration %1</source>
        <translation>nel VAR_GLOBAL della configurazione %1</translation>
    </message>
    <message>
        <source>in the global variable list %1</source>
        <translation>nella lista delle variabili globali %1</translation>
    </message>
    <message>
        <source>The declared variables (page %1) are the program&apos;s global variables, %2.</source>
        <translation>Le variabili dichiarate (pagina %1) sono le variabili globali del programma, %2.</translation>
    </message>
    <message>
        <source>The generator adds these:</source>
        <translation>Il generatore aggiunge queste:</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Pagina %1 di %2</translation>
    </message>
    <message>
        <source>PackML chart</source>
        <translation>Diagramma PackML</translation>
    </message>
    <message>
        <source>Commands, modes and variables</source>
        <translation>Comandi, modalità e variabili</translation>
    </message>
    <message>
        <source>Unit mode %1</source>
        <translation>Modalità dell&apos;unità %1</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Comandi</translation>
    </message>
    <message>
        <source>Unit modes</source>
        <translation>Modalità dell&apos;unità</translation>
    </message>
    <message>
        <source>PackML, 2022 edition</source>
        <translation>PackML, edizione 2022</translation>
    </message>
    <message>
        <source>PackML, 2015 edition</source>
        <translation>PackML, edizione 2015</translation>
    </message>
    <message>
        <source>Hold accepted in Suspended</source>
        <translation>Hold accettato in Suspended</translation>
    </message>
    <message>
        <source>Complete accepted in Suspended and Held</source>
        <translation>Complete accettato in Suspended e Held</translation>
    </message>
    <message>
        <source>%1; options: %2</source>
        <translation>%1; opzioni: %2</translation>
    </message>
    <message>
        <source>Template</source>
        <translation>Modello</translation>
    </message>
    <message>
        <source>Initial unit mode</source>
        <translation>Modalità iniziale dell&apos;unità</translation>
    </message>
    <message>
        <source>PackML specification</source>
        <translation>Specifica PackML</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Comando</translation>
    </message>
    <message>
        <source>CntrlCmd</source>
        <translation>CntrlCmd</translation>
    </message>
    <message>
        <source>The commands of the edition, with the condition whose rising edge issues each one (besides CntrlCmd). A command a state does not accept is ignored there.</source>
        <translation>I comandi dell&apos;edizione, con la condizione il cui fronte di salita emette ciascuno (oltre a CntrlCmd). Un comando che uno stato non accetta vi è ignorato.</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modalità</translation>
    </message>
    <message>
        <source>Request condition</source>
        <translation>Condizione di richiesta</translation>
    </message>
    <message>
        <source>Disabled states</source>
        <translation>Stati disattivati</translation>
    </message>
    <message>
        <source>Mode change allowed in</source>
        <translation>Cambio di modalità permesso in</translation>
    </message>
    <message>
        <source>The unit modes, in number order. A mode skips its disabled states; the unit changes to a mode when its request condition rises while the current mode allows a change in the current state.</source>
        <translation>Le modalità dell&apos;unità, in ordine di numero. Una modalità salta i suoi stati disattivati; l&apos;unità passa a una modalità quando la sua condizione di richiesta sale mentre la modalità corrente permette un cambio nello stato corrente.</translation>
    </message>
    <message>
        <source>Nested GRAFCET</source>
        <translation>GRAFCET annidato</translation>
    </message>
    <message>
        <source>Nested GRAFCETs in %1</source>
        <translation>GRAFCET annidati in %1</translation>
    </message>
    <message>
        <source>None: the mode disables this state</source>
        <translation>Nessuno: la modalità disattiva questo stato</translation>
    </message>
    <message>
        <source>Own: %1</source>
        <translation>Proprio: %1</translation>
    </message>
    <message>
        <source>Same as mode %1: %2</source>
        <translation>Lo stesso della modalità %1: %2</translation>
    </message>
    <message>
        <source>Same as mode %1, which does not exist</source>
        <translation>Lo stesso della modalità %1, che non esiste</translation>
    </message>
    <message>
        <source>None: the state completes at once</source>
        <translation>Nessuno: lo stato si completa subito</translation>
    </message>
    <message>
        <source>None: Execute waits for a command</source>
        <translation>Nessuno: Execute attende un comando</translation>
    </message>
    <message>
        <source>Nested GRAFCET %1, continued</source>
        <translation>GRAFCET annidato %1, continua</translation>
    </message>
    <message>
        <source>GG Studio generates the PLC program as IEC 61131-3 Structured Text by the PackML design pattern: the program %1 is the state and mode manager, with the PackTags interface; it calls, in each acting state and Execute, the function block instance of the current unit mode and state, whose State Complete ends that state. This outline gives the program organisation units and their interfaces; File &gt; Export Structured Text and Export PLCopen XML write the code itself.</source>
        <translation>GG Studio genera il programma del PLC in testo strutturato IEC 61131-3 secondo il pattern di progettazione PackML: il programma %1 è il gestore di stati e modalità, con l&apos;interfaccia PackTags; chiama, in ogni stato attivo e in Execute, l&apos;istanza di blocco funzione della modalità dell&apos;unità e dello stato correnti, il cui State Complete termina quello stato. Questo schema riporta le unità di organizzazione del programma e le loro interfacce; File &gt; Esporta testo strutturato ed Esporta PLCopen XML scrivono il codice stesso.</translation>
    </message>
    <message>
        <source>The PackML state and mode manager: it latches the commands and mode requests, holds the current state and unit mode in StateCurrent and UnitModeCurrent, evaluates the current state&apos;s transitions in the current mode and calls the function block instance of that mode and state.</source>
        <translation>Il gestore di stati e modalità PackML: memorizza i comandi e le richieste di modalità, tiene lo stato e la modalità dell&apos;unità correnti in StateCurrent e UnitModeCurrent, valuta le transizioni dello stato corrente nella modalità corrente e chiama l&apos;istanza di blocco funzione di quella modalità e di quello stato.</translation>
    </message>
    <message>
        <source>The nested GRAFCET %1 (page %2). %3 calls it while the unit is in %4 in a mode that runs it; its Complete is that state&apos;s State Complete.</source>
        <translation>Il GRAFCET annidato %1 (pagina %2). %3 lo chiama mentre l&apos;unità è in %4 in una modalità che lo esegue; il suo Complete è lo State Complete di quello stato.</translation>
    </message>
    <message>
        <source>The function block of %1 in the modes without a GRAFCET there: %2</source>
        <translation>Il blocco funzione di %1 nelle modalità senza GRAFCET lì: %2</translation>
    </message>
    <message>
        <source>it completes at once.</source>
        <translation>si completa subito.</translation>
    </message>
    <message>
        <source>it does nothing, Execute waits for a command.</source>
        <translation>non fa nulla, Execute attende un comando.</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Macchina</translation>
    </message>
    <message>
        <source>Component</source>
        <translation>Componente</translation>
    </message>
    <message>
        <source>Wiring</source>
        <translation>Cablaggio</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Impostazioni</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>illimitato</translation>
    </message>
    <message>
        <source>Feeds %1</source>
        <translation>Alimenta %1</translation>
    </message>
    <message>
        <source>The virtual machine the simulation runs the program against, in closed loop: after each scan the components move one cycle time from the outputs wired to them and set the sensors the next scan reads; operator inputs stay the user&apos;s. Times are in milliseconds, counted in whole cycles.</source>
        <translation>La macchina virtuale contro cui la simulazione esegue il programma, in anello chiuso: dopo ogni ciclo i componenti si muovono di un tempo di ciclo secondo le uscite cablate a essi e impostano i sensori che il ciclo successivo legge; gli ingressi dell&apos;operatore restano dell&apos;utente. I tempi sono in millisecondi, contati in cicli interi.</translation>
    </message>
    <message>
        <source>The machine at rest</source>
        <translation>La macchina a riposo</translation>
    </message>
</context>
<context>
    <name>StateNames</name>
    <message>
        <source>Stop in initial state</source>
        <translation>Arresto nello stato iniziale</translation>
    </message>
    <message>
        <source>Stop requested at end of cycle</source>
        <translation>Arresto richiesto a fine ciclo</translation>
    </message>
    <message>
        <source>Stop requested in a given state</source>
        <translation>Arresto richiesto in uno stato determinato</translation>
    </message>
    <message>
        <source>Stop obtained</source>
        <translation>Arresto ottenuto</translation>
    </message>
    <message>
        <source>Preparation for restart after failure</source>
        <translation>Preparazione per la rimessa in marcia dopo un guasto</translation>
    </message>
    <message>
        <source>Operative part reset to initial state</source>
        <translation>Messa della parte operativa nello stato iniziale</translation>
    </message>
    <message>
        <source>Operative part set to a given state</source>
        <translation>Messa della parte operativa in uno stato determinato</translation>
    </message>
    <message>
        <source>Normal production</source>
        <translation>Produzione normale</translation>
    </message>
    <message>
        <source>Preparation run</source>
        <translation>Marcia di preparazione</translation>
    </message>
    <message>
        <source>Closing run</source>
        <translation>Marcia di chiusura</translation>
    </message>
    <message>
        <source>Verification run out of order</source>
        <translation>Marcia di verifica in disordine</translation>
    </message>
    <message>
        <source>Verification run in order</source>
        <translation>Marcia di verifica in ordine</translation>
    </message>
    <message>
        <source>Test run</source>
        <translation>Marcia di prova</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Arresto di emergenza</translation>
    </message>
    <message>
        <source>Diagnosis and/or failure handling</source>
        <translation>Diagnosi e/o trattamento del guasto</translation>
    </message>
    <message>
        <source>Production despite failure</source>
        <translation>Produzione nonostante il guasto</translation>
    </message>
    <message>
        <source>Stop procedures</source>
        <translation>Procedure di arresto</translation>
    </message>
    <message>
        <source>Operation procedures</source>
        <translation>Procedure di funzionamento</translation>
    </message>
    <message>
        <source>Failure procedures</source>
        <translation>Procedure di guasto</translation>
    </message>
</context>
<context>
    <name>ValueProblemText</name>
    <message>
        <source>&apos;%1&apos; is not an %2 literal: write a whole number such as 42</source>
        <extracomment>%1: the value as written; %2: INT</extracomment>
        <translation>&apos;%1&apos; non è un letterale %2: scrivere un numero intero, ad esempio 42</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a %2 literal: write a whole number such as 42</source>
        <extracomment>%1: the value as written; %2: an integer type other than INT (SINT, UDINT...)</extracomment>
        <translation>&apos;%1&apos; non è un letterale %2: scrivere un numero intero, ad esempio 42</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has leading or trailing spaces</source>
        <translation>&apos;%1&apos; ha spazi all&apos;inizio o alla fine</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a BOOL literal (TRUE or FALSE)</source>
        <translation>&apos;%1&apos; non è un letterale BOOL (TRUE o FALSE)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a %2 literal: write a decimal number such as 1.5 or 2.0E3</source>
        <extracomment>%1: the value as written; %2: REAL or LREAL</extracomment>
        <translation>&apos;%1&apos; non è un letterale %2: scrivere un numero decimale, ad esempio 1.5 o 2.0E3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range for %2 (%3..%4)</source>
        <extracomment>%1: the value as written; %2: its IEC type; %3..%4: the type&apos;s range</extracomment>
        <translation>&apos;%1&apos; è fuori dall&apos;intervallo di %2 (%3..%4)</translation>
    </message>
</context>
<context>
    <name>editor::Autosave</name>
    <message>
        <source>Cannot create the folder %1 for recovery copies</source>
        <translation>Impossibile creare la cartella %1 per le copie di recupero</translation>
    </message>
    <message>
        <source>Cannot write the recovery copy: %1</source>
        <translation>Impossibile scrivere la copia di recupero: %1</translation>
    </message>
    <message>
        <source>Cannot lock the recovery copy %1</source>
        <translation>Impossibile bloccare la copia di recupero %1</translation>
    </message>
    <message>
        <source>Another GG Studio is using the recovery copy %1.</source>
        <translation>Un&apos;altra istanza di GG Studio sta usando la copia di recupero %1.</translation>
    </message>
</context>
<context>
    <name>editor::BranchDrag</name>
    <message>
        <source>Step %1 is on no branch of a divergence: there is no branch to move</source>
        <translation>La tappa %1 non è su alcun ramo di una divergenza: non c’è alcun ramo da spostare</translation>
    </message>
    <message>
        <source>Move the branch of step %1 left in %2</source>
        <translation>Sposta il ramo della tappa %1 a sinistra in %2</translation>
    </message>
    <message>
        <source>Move the branch of step %1 right in %2</source>
        <translation>Sposta il ramo della tappa %1 a destra in %2</translation>
    </message>
</context>
<context>
    <name>editor::ChartContextMenu</name>
    <message>
        <source>&amp;Show %1</source>
        <translation>&amp;Mostra %1</translation>
    </message>
    <message>
        <source>&amp;Hide %1</source>
        <translation>&amp;Nascondi %1</translation>
    </message>
    <message>
        <source>Step &amp;Type</source>
        <translation>&amp;Tipo di tappa</translation>
    </message>
    <message>
        <source>Make &amp;Initial Step</source>
        <translation>Rendi tappa &amp;iniziale</translation>
    </message>
    <message>
        <source>Edit &amp;Comment…</source>
        <translation>Modifica il &amp;commento…</translation>
    </message>
    <message>
        <source>Edit &amp;Condition…</source>
        <translation>Modifica la &amp;condizione…</translation>
    </message>
    <message>
        <source>&amp;Negated</source>
        <translation>&amp;Negata</translation>
    </message>
    <message>
        <source>Flips whether this transition waits for Complete of its source&apos;s nested behaviour</source>
        <translation>Inverte l&apos;attesa da parte di questa transizione di Complete del comportamento annidato della sua tappa di origine</translation>
    </message>
    <message>
        <source>Priority &amp;Up</source>
        <translation>&amp;Alza la priorità</translation>
    </message>
    <message>
        <source>Priority &amp;Down</source>
        <translation>&amp;Abbassa la priorità</translation>
    </message>
    <message numerus="yes">
        <source>Hide the %n Selected Elements</source>
        <translation>
            <numerusform>Nascondi l&apos;elemento selezionato</numerusform>
            <numerusform>Nascondi i %n elementi selezionati</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show the %n Selected Elements</source>
        <translation>
            <numerusform>Mostra l&apos;elemento selezionato</numerusform>
            <numerusform>Mostra gli %n elementi selezionati</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Open Nested GRAFCET</source>
        <translation>&amp;Apri il GRAFCET annidato</translation>
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
        <translation>Condizioni</translation>
    </message>
</context>
<context>
    <name>editor::ConnectTransitionDialog</name>
    <message>
        <source>Connect T%1 of %2</source>
        <extracomment>%1 the transition&apos;s number, %2 the GEMMA step whose GRAFCET it is in</extracomment>
        <translation>Collega T%1 di %2</translation>
    </message>
    <message>
        <source>Upstream steps (it leaves them)</source>
        <translation>Tappe a monte (le disattiva)</translation>
    </message>
    <message>
        <source>Downstream steps (it activates them)</source>
        <translation>Tappe a valle (le attiva)</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Tappa %1</translation>
    </message>
    <message>
        <source>Tick an upstream step: a transition leaves at least one step.</source>
        <translation>Spuntare una tappa a monte: una transizione lascia almeno una tappa.</translation>
    </message>
    <message>
        <source>Tick a downstream step: a transition activates at least one step. To end a branch on a step with no transition after it, use Add Branch Ending on a Step on the step.</source>
        <translation>Spuntare una tappa a valle: una transizione attiva almeno una tappa. Per terminare un ramo su una tappa senza transizione dopo, usare «Aggiungi ramo che termina su una tappa» sulla tappa.</translation>
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
        <translation>Senza titolo</translation>
    </message>
    <message>
        <source>Stop the simulation to edit the model</source>
        <translation>Termina la simulazione per modificare il modello</translation>
    </message>
</context>
<context>
    <name>editor::ExportActions</name>
    <message>
        <source>Export &amp;PLCopen XML…</source>
        <translation>Esporta &amp;PLCopen XML…</translation>
    </message>
    <message>
        <source>Write the PLC program as PLCopen XML, to import into a PLC programming tool</source>
        <translation>Scrivi il programma PLC in PLCopen XML, da importare in un ambiente di programmazione PLC</translation>
    </message>
    <message>
        <source>Export &amp;Structured Text…</source>
        <translation>Esporta &amp;Testo strutturato (ST)…</translation>
    </message>
    <message>
        <source>Write the PLC program as IEC 61131-3 Structured Text files</source>
        <translation>Scrivi il programma PLC come file in Testo strutturato (ST) IEC 61131-3</translation>
    </message>
    <message>
        <source>Export &amp;GG-Generator JSON…</source>
        <translation>Esporta JSON &amp;GG-Generator…</translation>
    </message>
    <message>
        <source>Save the model in the format of the GG-Generator web tool</source>
        <translation>Salva il modello nel formato dello strumento web GG-Generator</translation>
    </message>
    <message>
        <source>Export &amp;Chart…</source>
        <translation>Esporta &amp;diagramma…</translation>
    </message>
    <message>
        <source>Save the chart as an SVG, PNG or PDF picture</source>
        <translation>Salva il diagramma come immagine SVG, PNG o PDF</translation>
    </message>
    <message>
        <source>&amp;Print…</source>
        <translation>Sta&amp;mpa…</translation>
    </message>
    <message>
        <source>Print the chart</source>
        <translation>Stampa il diagramma</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… e %n altro</numerusform>
            <numerusform>… e altri %n</numerusform>
        </translation>
    </message>
    <message>
        <source>Export a Model with Errors</source>
        <translation>Esporta un modello con errori</translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s). The generated code marks each one with a comment, but it may not compile or may not behave as intended.</source>
        <translation>
            <numerusform>Il modello ha %n errore. Il codice generato lo segnala con un commento, ma potrebbe non compilare o non comportarsi come previsto.</numerusform>
            <numerusform>Il modello ha %n errori. Il codice generato li segnala ciascuno con un commento, ma potrebbe non compilare o non comportarsi come previsto.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Export Anyway</source>
        <translation>Esporta &amp;comunque</translation>
    </message>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Esporta PLCopen XML</translation>
    </message>
    <message>
        <source>PLCopen XML (*.xml)</source>
        <translation>PLCopen XML (*.xml)</translation>
    </message>
    <message>
        <source>Export Structured Text</source>
        <translation>Esporta Testo strutturato</translation>
    </message>
    <message>
        <source>Structured Text (*.st)</source>
        <translation>Testo strutturato (*.st)</translation>
    </message>
    <message>
        <source>Export Structured Text to a Folder</source>
        <translation>Esporta Testo strutturato in una cartella</translation>
    </message>
    <message>
        <source>Export GG-Generator JSON</source>
        <translation>Esporta JSON GG-Generator</translation>
    </message>
    <message>
        <source>GG-Generator JSON (*.json)</source>
        <translation>JSON GG-Generator (*.json)</translation>
    </message>
    <message>
        <source>SVG picture (*.svg)</source>
        <translation>Immagine SVG (*.svg)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Immagine PNG (*.png)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Documento PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export Chart</source>
        <translation>Esporta diagramma</translation>
    </message>
    <message>
        <source>Print Chart</source>
        <translation>Stampa diagramma</translation>
    </message>
    <message>
        <source>The printer could not be started.</source>
        <translation>Impossibile avviare la stampante.</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>Esportato in %1</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Esportazione non riuscita</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>Impossibile scrivere %1.</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>senza titolo</translation>
    </message>
    <message>
        <source>The nested GRAFCETs of %1: GG-Generator has no place for nested behaviour.</source>
        <translation>I GRAFCET annidati di %1: GG-Generator non ha posto per il comportamento annidato.</translation>
    </message>
    <message>
        <source>The variable kinds (output, internal): GG-Generator reads every variable as an input.</source>
        <translation>I generi delle variabili (uscita, interna): GG-Generator legge ogni variabile come ingresso.</translation>
    </message>
    <message>
        <source>The until-stable evolution rule: GG-Generator knows one evolution per scan only.</source>
        <translation>La regola di evoluzione «fino alla stabilità»: GG-Generator conosce solo un&apos;evoluzione per ciclo.</translation>
    </message>
    <message>
        <source>Export to GG-Generator</source>
        <translation>Esporta per GG-Generator</translation>
    </message>
    <message>
        <source>The GG-Generator file will leave out part of this model. Your model and its own file keep everything.</source>
        <translation>Il file GG-Generator tralascerà una parte di questo modello. Il modello e il suo file conservano tutto.</translation>
    </message>
    <message>
        <source>%1, nested GRAFCET of %2</source>
        <translation>%1, GRAFCET annidato di %2</translation>
    </message>
    <message>
        <source>Export Speci&amp;fication…</source>
        <translation>Esporta la speci&amp;fica…</translation>
    </message>
    <message>
        <source>Write the whole model as one PDF document: the chart, the states, the variables, every nested GRAFCET and the outline of the generated code</source>
        <translation>Scrivere l&apos;intero modello come un unico documento PDF: il diagramma, gli stati, le variabili, ogni GRAFCET annidato e lo schema del codice generato</translation>
    </message>
    <message>
        <source>Export Specification</source>
        <translation>Esporta la specifica</translation>
    </message>
    <message>
        <source>The verification properties: GG-Generator has no place for them.</source>
        <translation>Le proprietà da verificare: GG-Generator non ha posto per esse.</translation>
    </message>
    <message>
        <source>Writing the specification…</source>
        <translation>Scrittura della specifica…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annulla</translation>
    </message>
    <message>
        <source>Export cancelled: %1 left unchanged</source>
        <translation>Esportazione annullata: %1 non è stato modificato</translation>
    </message>
</context>
<context>
    <name>editor::ExportOptionsDialog</name>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Esporta PLCopen XML</translation>
    </message>
    <message>
        <source>Export Structured Text</source>
        <translation>Esporta Testo strutturato</translation>
    </message>
    <message>
        <source>One file per POU, in a &amp;folder</source>
        <translation>Un file per POU, in una &amp;cartella</translation>
    </message>
    <message>
        <source>One &amp;IEC 61131-3 file with every POU</source>
        <translation>Un unico file &amp;IEC 61131-3 con tutte le POU</translation>
    </message>
    <message>
        <source>Files:</source>
        <translation>File:</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialetto:</translation>
    </message>
    <message>
        <source>IEC writes PLCopen TC6 XML 2.01 with the globals in the configuration. CODESYS writes what CODESYS V3.5 imports, with a GVL.</source>
        <translation>IEC scrive PLCopen TC6 XML 2.01 con le variabili globali nella configurazione. CODESYS scrive ciò che CODESYS V3.5 importa, con una GVL.</translation>
    </message>
    <message>
        <source>The single file is always IEC 61131-3: CODESYS code names a GVL that IEC compilers do not know.</source>
        <translation>Il file unico è sempre IEC 61131-3: il codice CODESYS fa riferimento a una GVL che i compilatori IEC non conoscono.</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Esporta…</translation>
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
        <translation>Inserisci tappa &amp;dopo</translation>
    </message>
    <message>
        <source>Insert Step &amp;Before</source>
        <translation>Inserisci tappa &amp;prima</translation>
    </message>
    <message>
        <source>Add &amp;Selection Branch</source>
        <translation>Aggiungi ramo di &amp;selezione</translation>
    </message>
    <message>
        <source>Add &amp;Parallel Branch</source>
        <translation>Aggiungi ramo p&amp;arallelo</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Rimuovi</translation>
    </message>
    <message>
        <source>Remove Bra&amp;nch</source>
        <translation>Rimuovi ra&amp;mo</translation>
    </message>
    <message>
        <source>Ren&amp;umber Steps and Transitions</source>
        <translation>Ri&amp;numera tappe e transizioni</translation>
    </message>
    <message>
        <source>&amp;Connect Directly…</source>
        <translation>&amp;Collega direttamente…</translation>
    </message>
    <message>
        <source>&amp;Copy Steps</source>
        <translation>C&amp;opia tappe</translation>
    </message>
    <message>
        <source>&amp;Paste Steps</source>
        <translation>Incoll&amp;a tappe</translation>
    </message>
    <message>
        <source>Create the &amp;Usual Shape</source>
        <translation>Crea la forma &amp;usuale</translation>
    </message>
    <message>
        <source>Initial step 1, then step 2, then step 3, which sets Complete</source>
        <translation>Tappa iniziale 1, poi tappa 2, poi tappa 3, che imposta Complete</translation>
    </message>
    <message>
        <source>%1 has no GRAFCET yet.&lt;br&gt;&lt;a href=&quot;create&quot;&gt;Create the usual shape&lt;/a&gt;: initial step 1, step 2, and step 3, which sets Complete.</source>
        <extracomment>%1 the GEMMA step; the link creates its GRAFCET</extracomment>
        <translation>%1 non ha ancora un GRAFCET.&lt;br&gt;&lt;a href=&quot;create&quot;&gt;Crea la forma usuale&lt;/a&gt;: tappa iniziale 1, tappa 2 e tappa 3, che imposta Complete.</translation>
    </message>
    <message>
        <source>Add Loop or &amp;Jump To</source>
        <translation>Aggiungi ciclo o &amp;salto verso</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Tappa %1</translation>
    </message>
    <message>
        <source>Add step %1 to %2</source>
        <translation>Aggiungi la tappa %1 a %2</translation>
    </message>
    <message>
        <source>Add selection branch to %1</source>
        <translation>Aggiungi un ramo di selezione a %1</translation>
    </message>
    <message>
        <source>Add parallel branch to %1</source>
        <translation>Aggiungi un ramo parallelo a %1</translation>
    </message>
    <message>
        <source>Add jump from step %1 to step %2 in %3</source>
        <extracomment>%1 and %2 step numbers, %3 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Aggiungi un salto dalla tappa %1 alla tappa %2 in %3</translation>
    </message>
    <message>
        <source>Remove step %1 from %2</source>
        <translation>Rimuovi la tappa %1 da %2</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n steps from %1</source>
        <translation>
            <numerusform>Rimuovi %n tappa da %1</numerusform>
            <numerusform>Rimuovi %n tappe da %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Remove branch from %1</source>
        <translation>Rimuovi un ramo da %1</translation>
    </message>
    <message>
        <source>Renumber %1</source>
        <translation>Rinumera %1</translation>
    </message>
    <message>
        <source>Connect %1 T%2</source>
        <extracomment>%1 the GEMMA step, %2 the transition&apos;s number</extracomment>
        <translation>Collega %1 T%2</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n steps into %1</source>
        <translation>
            <numerusform>Incolla %n tappa in %1</numerusform>
            <numerusform>Incolla %n tappe in %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Create GRAFCET of %1</source>
        <translation>Crea il GRAFCET di %1</translation>
    </message>
    <message>
        <source>Add Branch &amp;Ending on a Step</source>
        <translation>Aggiungi ramo che &amp;termina su una tappa</translation>
    </message>
    <message>
        <source>A new branch from this step to a new step with no transition after it (an exit step)</source>
        <translation>Un nuovo ramo da questa tappa a una nuova tappa senza transizione dopo (una tappa di uscita)</translation>
    </message>
    <message>
        <source>Move Branch &amp;Left</source>
        <translation>Sposta il ramo a &amp;sinistra</translation>
    </message>
    <message>
        <source>Swap the branch holding this step with the one at its left</source>
        <translation>Scambia il ramo che contiene questa tappa con quello alla sua sinistra</translation>
    </message>
    <message>
        <source>Move Branch Ri&amp;ght</source>
        <translation>Sposta il ramo a &amp;destra</translation>
    </message>
    <message>
        <source>Swap the branch holding this step with the one at its right</source>
        <translation>Scambia il ramo che contiene questa tappa con quello alla sua destra</translation>
    </message>
    <message>
        <source>Cu&amp;t Steps</source>
        <translation>&amp;Taglia tappe</translation>
    </message>
    <message>
        <source>Add branch ending on a step at step %1 in %2</source>
        <extracomment>%1 the step the branch leaves, %2 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Aggiungi ramo che termina su una tappa alla tappa %1 di %2</translation>
    </message>
    <message>
        <source>Move branch left in %1</source>
        <extracomment>%1 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Sposta un ramo a sinistra in %1</translation>
    </message>
    <message>
        <source>Move branch right in %1</source>
        <translation>Sposta un ramo a destra in %1</translation>
    </message>
    <message>
        <source>Remove T%1 from %2</source>
        <translation>Rimuovi T%1 da %2</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n transitions from %1</source>
        <translation>
            <numerusform>Rimuovi %n transizione da %1</numerusform>
            <numerusform>Rimuovi %n transizioni da %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remove %n elements from %1</source>
        <translation>
            <numerusform>Rimuovi %n elemento da %1</numerusform>
            <numerusform>Rimuovi %n elementi da %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Cut step %1 from %2</source>
        <translation>Taglia la tappa %1 da %2</translation>
    </message>
    <message numerus="yes">
        <source>Cut %n steps from %1</source>
        <translation>
            <numerusform>Taglia %n tappa da %1</numerusform>
            <numerusform>Taglia %n tappe da %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::GrafcetActionsModel</name>
    <message>
        <source>When</source>
        <translation>Quando</translation>
    </message>
    <message>
        <source>Qual.</source>
        <extracomment>short: the column is narrow; its tooltip says &quot;qualifier&quot; in full</extracomment>
        <translation>Qual.</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variabile</translation>
    </message>
    <message>
        <source>IF / value</source>
        <extracomment>the condition after IF of an N action, or the value of a := action; short: the column is narrow</extracomment>
        <translation>IF / valore</translation>
    </message>
    <message>
        <source>While the step is active (N), or once when it is activated or deactivated (S, R, :=)</source>
        <translation>Finché la tappa è attiva (N), o una volta alla sua attivazione o disattivazione (S, R, :=)</translation>
    </message>
    <message>
        <source>Qualifier. N: the variable is TRUE while the step is active
S, R: set it TRUE or FALSE
:=: assign it the value</source>
        <translation>Qualificatore. N: la variabile è TRUE finché la tappa è attiva
S, R: impostarla a TRUE o FALSE
:=: assegnarle il valore</translation>
    </message>
    <message>
        <source>An output or internal variable, or Complete</source>
        <translation>Una variabile di uscita o interna, o Complete</translation>
    </message>
    <message>
        <source>N: only IF this condition holds (may be empty)
:=: the value assigned</source>
        <translation>N: solo IF questa condizione è vera (può essere vuota)
:=: il valore assegnato</translation>
    </message>
    <message>
        <source>While active</source>
        <translation>Finché attiva</translation>
    </message>
    <message>
        <source>On activation</source>
        <translation>All’attivazione</translation>
    </message>
    <message>
        <source>On deactivation</source>
        <translation>Alla disattivazione</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetSimulationMarks</name>
    <message>
        <source>%1 is active: its GRAFCET runs. Unstable: the last scan ended without a stable situation</source>
        <translation>%1 è attiva: il suo GRAFCET evolve. Unstable: l&apos;ultimo ciclo è finito senza una situazione stabile</translation>
    </message>
    <message>
        <source>%1 has just been entered: its GRAFCET starts from its initial steps in the next scan</source>
        <translation>%1 è appena stata attivata: il suo GRAFCET parte dalle sue tappe iniziali al prossimo ciclo</translation>
    </message>
    <message>
        <source>%1 is not active: its GRAFCET is shown greyed, as it was left</source>
        <translation>%1 non è attiva: il suo GRAFCET è mostrato in grigio, come è stato lasciato</translation>
    </message>
    <message numerus="yes">
        <source>%1 is active: its GRAFCET runs (step(s) %2)</source>
        <translation>
            <numerusform>%1 è attiva: il suo GRAFCET evolve (fase %2)</numerusform>
            <numerusform>%1 è attiva: il suo GRAFCET evolve (fasi %2)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 has just been resumed: its GRAFCET goes on where it was paused in the next scan</source>
        <translation>%1 è appena stato ripreso: il suo GRAFCET riprende da dove era stato sospeso nel prossimo ciclo</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetStepDock</name>
    <message>
        <source>Nested Step</source>
        <translation>Tappa annidata</translation>
    </message>
    <message>
        <source>Select a step in a nested GRAFCET&apos;s tab to see and edit its number, comment and actions.</source>
        <translation>Selezionare una tappa nella scheda di un GRAFCET annidato per vederne e modificarne numero, commento e azioni.</translation>
    </message>
    <message>
        <source>&amp;Number:</source>
        <translation>&amp;Numero:</translation>
    </message>
    <message>
        <source>Unique in this GRAFCET; its activity is X&lt;number&gt;. The transitions and the X&lt;number&gt; of the receptivities and actions follow a new number.</source>
        <translation>Unico in questo GRAFCET; la sua attività è X&lt;numero&gt;. Le transizioni e gli X&lt;numero&gt; delle ricettività e delle azioni seguono un nuovo numero.</translation>
    </message>
    <message>
        <source>&amp;Initial</source>
        <translation>&amp;Iniziale</translation>
    </message>
    <message>
        <source>Active when the GEMMA state is entered (a GRAFCET needs at least one)</source>
        <translation>Attiva all’ingresso nello stato GEMMA (un GRAFCET ne richiede almeno una)</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Commento:</translation>
    </message>
    <message>
        <source>What the machine does in this step</source>
        <translation>Ciò che la macchina fa in questa tappa</translation>
    </message>
    <message>
        <source>&amp;Actions:</source>
        <translation>&amp;Azioni:</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Aggiungi</translation>
    </message>
    <message>
        <source>Add an action after the current one</source>
        <translation>Aggiungi un’azione dopo quella corrente</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Rimuovi</translation>
    </message>
    <message>
        <source>Remove the current action</source>
        <translation>Rimuovi l’azione corrente</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Su</translation>
    </message>
    <message>
        <source>Run the current action earlier</source>
        <translation>Esegui prima l’azione corrente</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Giù</translation>
    </message>
    <message>
        <source>Run the current action later</source>
        <translation>Esegui dopo l’azione corrente</translation>
    </message>
    <message>
        <source>%1 step %2</source>
        <extracomment>A step of the nested GRAFCET of a GEMMA step: &quot;F1 step 3&quot;</extracomment>
        <translation>%1 tappa %2</translation>
    </message>
    <message>
        <source>In the nested GRAFCET of %1 %2</source>
        <translation>Nel GRAFCET annidato di %1 %2</translation>
    </message>
    <message>
        <source>%1 already has a step %2: choose another number.</source>
        <translation>%1 ha già una tappa %2: scegliere un altro numero.</translation>
    </message>
    <message>
        <source>Step numbers start at 1: %1 is not a step number.</source>
        <translation>I numeri di fase partono da 1: %1 non è un numero di fase.</translation>
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
        <translation>Il GRAFCET di %1 nel modo %2</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1</source>
        <translation>Il GRAFCET annidato di %1</translation>
    </message>
    <message>
        <source>PackML Chart</source>
        <translation>Diagramma PackML</translation>
    </message>
    <message>
        <source>GEMMA Chart</source>
        <translation>Diagramma GEMMA</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetTransitionDock</name>
    <message>
        <source>Nested Transition</source>
        <translation>Transizione annidata</translation>
    </message>
    <message>
        <source>Select a transition in a nested GRAFCET&apos;s tab to see and edit its receptivity.</source>
        <translation>Selezionare una transizione nella scheda di un GRAFCET annidato per vederne e modificarne la ricettività.</translation>
    </message>
    <message>
        <source>From steps:</source>
        <translation>Dalle tappe:</translation>
    </message>
    <message>
        <source>To steps:</source>
        <translation>Alle tappe:</translation>
    </message>
    <message>
        <source>Click a step to select it</source>
        <translation>Fare clic su una tappa per selezionarla</translation>
    </message>
    <message>
        <source>&amp;Receptivity:</source>
        <translation>&amp;Ricettività:</translation>
    </message>
    <message>
        <source>e.g. PartPresent AND X3, ↑Start, 5s/X2</source>
        <translation>es. PartPresent AND X3, ↑Start, 5s/X2</translation>
    </message>
    <message>
        <source>Structured Text as in GEMMA conditions, plus X3 (step 3 is active), ↑a or RE a (rising edge), ↓a or FE a (falling edge), 5s/X3 (step 3 active for 5 s) and Complete.
Ctrl+Space completes a name.</source>
        <translation>Testo strutturato come nelle condizioni GEMMA, più X3 (la tappa 3 è attiva), ↑a o RE a (fronte di salita), ↓a o FE a (fronte di discesa), 5s/X3 (la tappa 3 è attiva da 5 s) e Complete.
Ctrl+Spazio completa un nome.</translation>
    </message>
    <message>
        <source>%1 T%2</source>
        <extracomment>A transition of the nested GRAFCET of a GEMMA step: &quot;F1 T2&quot;</extracomment>
        <translation>%1 T%2</translation>
    </message>
    <message>
        <source>In the nested GRAFCET of %1 %2</source>
        <translation>Nel GRAFCET annidato di %1 %2</translation>
    </message>
</context>
<context>
    <name>editor::LinkDrag</name>
    <message>
        <source>A transition cannot be linked to a transition: steps and transitions alternate</source>
        <translation>Una transizione non può essere collegata a una transizione: tappe e transizioni si alternano</translation>
    </message>
    <message>
        <source>Step %1 already leads to step %2</source>
        <translation>La tappa %1 porta già alla tappa %2</translation>
    </message>
    <message>
        <source>Step %1 already precedes T%2</source>
        <translation>La tappa %1 precede già T%2</translation>
    </message>
    <message>
        <source>Step %1 already follows T%2</source>
        <translation>La tappa %1 segue già T%2</translation>
    </message>
    <message>
        <source>Step %1 cannot be linked to itself through one transition</source>
        <translation>La tappa %1 non può essere collegata a sé stessa tramite una sola transizione</translation>
    </message>
    <message>
        <source>Step %1 would be linked to itself through T%2</source>
        <translation>La tappa %1 sarebbe collegata a sé stessa tramite T%2</translation>
    </message>
    <message>
        <source>Drag onto a step or a transition to link them</source>
        <translation>Trascinare su una tappa o una transizione per collegarle</translation>
    </message>
    <message>
        <source>Link step %1 to step %2 in %3</source>
        <translation>Collega la tappa %1 alla tappa %2 in %3</translation>
    </message>
    <message>
        <source>Link step %1 to T%2 in %3</source>
        <translation>Collega la tappa %1 a T%2 in %3</translation>
    </message>
    <message>
        <source>Link T%1 to step %2 in %3</source>
        <translation>Collega T%1 alla tappa %2 in %3</translation>
    </message>
</context>
<context>
    <name>editor::MachineDock</name>
    <message>
        <source>Machine</source>
        <translation>Macchina</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Aggiungi</translation>
    </message>
    <message>
        <source>Add a component of the kind chosen beside</source>
        <translation>Aggiungi un componente del tipo scelto accanto</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Rimuovi</translation>
    </message>
    <message>
        <source>Remove the selected component and its wiring</source>
        <translation>Rimuovi il componente selezionato e il suo cablaggio</translation>
    </message>
    <message>
        <source>The model has no machine yet. Add its components to simulate in closed loop: the machine then sets the sensors.</source>
        <translation>Il modello non ha ancora una macchina. Aggiungi i suoi componenti per simulare ad anello chiuso: la macchina imposta allora i sensori.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>(not wired)</source>
        <translation>(non cablato)</translation>
    </message>
    <message>
        <source>A BOOL output of the program, which drives the component</source>
        <translation>Un&apos;uscita BOOL del programma, che comanda il componente</translation>
    </message>
    <message>
        <source>A BOOL input of the program, which the component sets</source>
        <translation>Un ingresso BOOL del programma, che il componente imposta</translation>
    </message>
    <message>
        <source>Unlimited</source>
        <translation>Illimitato</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>Contatto</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(nessuno)</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>Alimenta</translation>
    </message>
</context>
<context>
    <name>editor::MachineTab</name>
    <message>
        <source>Machine</source>
        <translation>Macchina</translation>
    </message>
    <message>
        <source>The virtual machine: its components, moving as the simulation runs</source>
        <translation>La macchina virtuale: i suoi componenti, che si muovono durante la simulazione</translation>
    </message>
</context>
<context>
    <name>editor::MainWindow</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Salvataggio automatico non riuscito: %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Modifica</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Lingua</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nuovo</translation>
    </message>
    <message>
        <source>Start a new model from the GEMMA template</source>
        <translation>Crea un nuovo modello dal template GEMMA</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Apri…</translation>
    </message>
    <message>
        <source>Open a GG Studio model, a GG-Generator file or an exported PLCopen XML file</source>
        <translation>Apri un modello GG Studio, un file GG-Generator o un file PLCopen XML esportato</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Salva</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Salva con n&amp;ome…</translation>
    </message>
    <message>
        <source>&amp;Reset to Template…</source>
        <translation>&amp;Ripristina il template…</translation>
    </message>
    <message>
        <source>Put every state, transition, variable and setting back to the template</source>
        <translation>Riporta ogni stato, transizione, variabile e impostazione al template</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annulla</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annulla %1</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Ripeti</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Ripeti %1</translation>
    </message>
    <message>
        <source>&amp;Model Settings…</source>
        <translation>&amp;Impostazioni del modello…</translation>
    </message>
    <message>
        <source>Model name, PLC cycle time and code dialect</source>
        <translation>Nome del modello, tempo di ciclo del PLC e dialetto del codice</translation>
    </message>
    <message>
        <source>Show &amp;Hidden Elements</source>
        <translation>Mostra elementi &amp;nascosti</translation>
    </message>
    <message>
        <source>Draw the hidden states and transitions faded, so they can be selected</source>
        <translation>Disegna sbiaditi gli stati e le transizioni nascosti, in modo da poterli selezionare</translation>
    </message>
    <message>
        <source>&amp;Actual Size (100 %)</source>
        <translation>&amp;Dimensioni reali (100 %)</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>&amp;Ingrandisci</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Riduci</translation>
    </message>
    <message>
        <source>&amp;About GG Studio</source>
        <translation>&amp;Informazioni su GG Studio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Informazioni su &amp;Qt</translation>
    </message>
    <message>
        <source>%1[*] — GG Studio</source>
        <translation>%1[*] — GG Studio</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Modifiche non salvate</translation>
    </message>
    <message>
        <source>The model “%1” has unsaved changes.</source>
        <translation>Il modello «%1» ha modifiche non salvate.</translation>
    </message>
    <message>
        <source>Do you want to save them?</source>
        <translation>Vuoi salvarle?</translation>
    </message>
    <message>
        <source>All supported files (*.json *.xml)</source>
        <translation>Tutti i file supportati (*.json *.xml)</translation>
    </message>
    <message>
        <source>GG Studio models (*.json)</source>
        <translation>Modelli GG Studio (*.json)</translation>
    </message>
    <message>
        <source>GG-Generator files (*.json)</source>
        <translation>File GG-Generator (*.json)</translation>
    </message>
    <message>
        <source>GG Studio PLCopen XML (*.xml)</source>
        <translation>PLCopen XML di GG Studio (*.xml)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Tutti i file (*)</translation>
    </message>
    <message>
        <source>Open Model</source>
        <translation>Apri modello</translation>
    </message>
    <message>
        <source>Could not open %1.</source>
        <translation>Impossibile aprire %1.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Aperto %1</translation>
    </message>
    <message>
        <source>Imported %1: Save As keeps it as a GG Studio model</source>
        <translation>Importato %1: «Salva con nome» lo conserva come modello GG Studio</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>senza titolo</translation>
    </message>
    <message>
        <source>Save Model As</source>
        <translation>Salva modello con nome</translation>
    </message>
    <message>
        <source>Save Model</source>
        <translation>Salva modello</translation>
    </message>
    <message>
        <source>Could not save %1.</source>
        <translation>Impossibile salvare %1.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Salvato %1</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Esportazione non riuscita</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>Impossibile scrivere %1.</translation>
    </message>
    <message>
        <source>Recovered unsaved changes: save them to keep them</source>
        <translation>Modifiche non salvate recuperate: salvale per conservarle</translation>
    </message>
    <message>
        <source>Reset to Template</source>
        <translation>Ripristina il template</translation>
    </message>
    <message>
        <source>Put every state, transition, variable and setting back to the GEMMA template? You can undo this.</source>
        <translation>Riportare ogni stato, transizione, variabile e impostazione al template GEMMA? L&apos;operazione si può annullare.</translation>
    </message>
    <message>
        <source>About GG Studio</source>
        <translation>Informazioni su GG Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;GG Studio %1&lt;/h3&gt;&lt;p&gt;An editor for the GEMMA-GRAFCET method: choose the operating modes of a machine on the GEMMA template, write the conditions of their transitions, and generate the IEC 61131-3 program that runs them (Structured Text, PLCopen XML).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;GG Studio %1&lt;/h3&gt;&lt;p&gt;Un editor per il metodo GEMMA-GRAFCET: scegli i modi di marcia e di arresto di una macchina sul template GEMMA, scrivi le condizioni delle loro transizioni e genera il programma IEC 61131-3 che li esegue (Testo strutturato, PLCopen XML).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulazione</translation>
    </message>
    <message>
        <source>&amp;Simulate</source>
        <translation>&amp;Simula</translation>
    </message>
    <message>
        <source>Run the model scan by scan; editing is locked while the simulation is on</source>
        <translation>Esegue il modello ciclo per ciclo; la modifica è bloccata durante la simulazione</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Esegui</translation>
    </message>
    <message>
        <source>Run scans at the speed set in the Simulation dock, or pause them</source>
        <translation>Esegue i cicli alla velocità impostata nel pannello Simulazione, o li mette in pausa</translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation>&amp;Un ciclo</translation>
    </message>
    <message>
        <source>R&amp;eset Simulation</source>
        <translation>&amp;Reimposta la simulazione</translation>
    </message>
    <message>
        <source>Simulation: editing locked</source>
        <translation>Simulazione: modifica bloccata</translation>
    </message>
    <message>
        <source>&amp;Verify</source>
        <translation>&amp;Verifica</translation>
    </message>
    <message>
        <source>Verifying…</source>
        <translation>Verifica in corso…</translation>
    </message>
    <message>
        <source>Verification failed: %1</source>
        <translation>Verifica non riuscita: %1</translation>
    </message>
    <message>
        <source>Verification finished: some properties do not hold (see Problems)</source>
        <translation>Verifica terminata: alcune proprietà non sono soddisfatte (vedi Problemi)</translation>
    </message>
    <message>
        <source>Verification finished: every property holds</source>
        <translation>Verifica terminata: tutte le proprietà sono soddisfatte</translation>
    </message>
    <message>
        <source>%1 counterexample</source>
        <translation>controesempio %1</translation>
    </message>
    <message>
        <source>Replay in Simulator</source>
        <translation>Riproduci nel simulatore</translation>
    </message>
    <message>
        <source>Could not replay %1.</source>
        <translation>Impossibile riprodurre %1.</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>Ese&amp;mpi</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>&amp;Ripristina la disposizione</translation>
    </message>
    <message>
        <source>Put the panels and the toolbar back where they were at the first start</source>
        <translation>Riportare i pannelli e la barra degli strumenti dove erano al primo avvio</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Barra degli strumenti principale</translation>
    </message>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Esporta PLCopen XML</translation>
    </message>
    <message>
        <source>Open Example</source>
        <translation>Apri esempio</translation>
    </message>
    <message>
        <source>Could not open the example “%1”.</source>
        <translation>Impossibile aprire l&apos;esempio «%1».</translation>
    </message>
    <message>
        <source>Opened the example “%1” as an untitled copy: Save As keeps your changes</source>
        <translation>Aperto l&apos;esempio «%1» come copia senza titolo: «Salva con nome» conserva le modifiche</translation>
    </message>
    <message>
        <source>&amp;Hide Selected Elements</source>
        <translation>&amp;Nascondi gli elementi selezionati</translation>
    </message>
    <message>
        <source>Hide the selected states and transitions: the machine does not need them</source>
        <translation>Nascondere gli stati e le transizioni selezionati: la macchina non ne ha bisogno</translation>
    </message>
    <message>
        <source>Sho&amp;w Selected Elements</source>
        <translation>&amp;Mostra gli elementi selezionati</translation>
    </message>
    <message>
        <source>Show the selected hidden states and transitions again</source>
        <translation>Mostrare di nuovo gli stati e le transizioni nascosti selezionati</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Guida utente</translation>
    </message>
    <message>
        <source>How to build a model, simulate, verify and export, offline; F1 opens it at the part about the panel you are in</source>
        <translation>Come costruire un modello, simularlo, verificarlo ed esportarlo, offline (in inglese); F1 la apre alla parte sul pannello in cui si trova</translation>
    </message>
    <message>
        <source>Step &amp;Back</source>
        <translation>Ciclo &amp;precedente</translation>
    </message>
    <message>
        <source>Show the previous scan of the run; a scan or Run from there continues from it and drops the later scans</source>
        <translation>Mostra il ciclo precedente dell&apos;esecuzione; un ciclo o Esegui da lì riprende da quel ciclo e scarta i cicli successivi</translation>
    </message>
    <message>
        <source>Step &amp;Forward</source>
        <translation>Ciclo su&amp;ccessivo</translation>
    </message>
    <message>
        <source>Show the next scan of the run&apos;s history</source>
        <translation>Mostra il ciclo successivo della cronologia dell&apos;esecuzione</translation>
    </message>
    <message>
        <source>Prove what the GEMMA layer and the nested GRAFCETs can and cannot do for every input sequence, and check your properties; the findings go to the Problems dock</source>
        <translation>Dimostrare ciò che il livello GEMMA e i GRAFCET annidati possono e non possono fare per ogni sequenza di ingressi, e verificare le tue proprietà; i risultati vanno nel pannello Problemi</translation>
    </message>
    <message>
        <source>Verify with &amp;Exact Time</source>
        <translation>Verifica con tempo e&amp;satto</translation>
    </message>
    <message>
        <source>Count time in scans when verifying: every timer elapses exactly when the PLC&apos;s would, instead of &quot;may or may not have elapsed&quot; (more states)</source>
        <translation>Contare il tempo in cicli durante la verifica: ogni temporizzatore scade esattamente quando scadrebbe quello del PLC, invece di &quot;può essere scaduto o no&quot; (più stati)</translation>
    </message>
    <message>
        <source>%1 was opened, but not everything in the file was taken over.</source>
        <translation>%1 è stato aperto, ma non tutto il contenuto del file è stato ripreso.</translation>
    </message>
    <message>
        <source>Verification finished: nothing is violated, but some properties are undecided (see Problems)</source>
        <translation>Verifica terminata: nulla è violato, ma alcune proprietà sono indecise (vedi Problemi)</translation>
    </message>
    <message>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Adatta alla finestra</translation>
    </message>
    <message>
        <source>Put every command, unit mode, GRAFCET, variable and setting back to a new PackML model of this edition? You can undo this.</source>
        <translation>Riportare ogni comando, modo di unità, GRAFCET, variabile e impostazione a un nuovo modello PackML di questa edizione? È possibile annullare.</translation>
    </message>
    <message>
        <source>Verify with the &amp;Machine</source>
        <translation>Verifica con la &amp;macchina</translation>
    </message>
    <message>
        <source>Explore the program with the model&apos;s machine: the sensors it drives follow the cylinders and conveyors instead of taking any value</source>
        <translation>Esplora il programma con la macchina del modello: i sensori che pilota seguono i cilindri e i nastri invece di prendere qualsiasi valore</translation>
    </message>
    <message>
        <source>Verification cancelled: the model, the Complete settings, the machine&apos;s use or Exact Time changed</source>
        <translation>Verifica annullata: sono cambiati il modello, le impostazioni di Complete, l&apos;uso della macchina o il tempo esatto</translation>
    </message>
    <message>
        <source>Co&amp;nnect…</source>
        <translation>Co&amp;nnetti…</translation>
    </message>
    <message>
        <source>Link the simulation to a digital twin, a soft PLC or an HMI over Modbus TCP; it then runs in real time</source>
        <translation>Collegare la simulazione a un gemello digitale, a un PLC software o a un HMI tramite Modbus TCP; allora gira in tempo reale</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Disconnetti</translation>
    </message>
    <message>
        <source>End the Modbus TCP link</source>
        <translation>Terminare il collegamento Modbus TCP</translation>
    </message>
    <message>
        <source>Verify with Single &amp;Faults</source>
        <translation>Verifica con &amp;guasti singoli</translation>
    </message>
    <message>
        <source>With the machine, also explore any one fault from any scan on: a sensor stuck or flickering, a cylinder or conveyor jammed</source>
        <translation>Con la macchina, esplorare anche un guasto qualsiasi a partire da qualunque ciclo: un sensore bloccato o intermittente, un cilindro o un nastro inceppato</translation>
    </message>
    <message>
        <source>The Modbus link is for GEMMA models; PackML models are not linked yet</source>
        <translation>Il collegamento Modbus è per i modelli GEMMA; i modelli PackML non sono ancora collegati</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Connetti</translation>
    </message>
    <message>
        <source>The Modbus link could not start: %1</source>
        <translation>Il collegamento Modbus non è potuto partire: %1</translation>
    </message>
    <message>
        <source>Undo</source>
        <extracomment>the Undo button of the toolbar (the Edit menu names the command)</extracomment>
        <translation>Annulla</translation>
    </message>
    <message>
        <source>Redo</source>
        <extracomment>the Redo button of the toolbar (the Edit menu names the command)</extracomment>
        <translation>Ripeti</translation>
    </message>
    <message>
        <source>Undo %1</source>
        <translation>Annulla %1</translation>
    </message>
    <message>
        <source>Redo %1</source>
        <translation>Ripeti %1</translation>
    </message>
</context>
<context>
    <name>editor::ModbusConnectDialog</name>
    <message>
        <source>Coil</source>
        <translation>Bobina</translation>
    </message>
    <message>
        <source>Discrete input</source>
        <translation>Ingresso discreto</translation>
    </message>
    <message>
        <source>Holding register</source>
        <translation>Registro di mantenimento</translation>
    </message>
    <message>
        <source>Input register</source>
        <translation>Registro di ingresso</translation>
    </message>
    <message>
        <source>Connect over Modbus TCP</source>
        <translation>Connetti tramite Modbus TCP</translation>
    </message>
    <message>
        <source>Server: the twin connects to the simulator</source>
        <translation>Server: il gemello si connette al simulatore</translation>
    </message>
    <message>
        <source>Client: the simulator connects to the twin</source>
        <translation>Client: il simulatore si connette al gemello</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variabile</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabella</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Indirizzo</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Modalità:</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Porta:</translation>
    </message>
    <message>
        <source>Unit id:</source>
        <translation>Id unità:</translation>
    </message>
    <message>
        <source>Load CSV…</source>
        <translation>Carica CSV…</translation>
    </message>
    <message>
        <source>Save As CSV…</source>
        <translation>Salva come CSV…</translation>
    </message>
    <message>
        <source>Default Map</source>
        <translation>Mappa predefinita</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Connetti</translation>
    </message>
    <message>
        <source>Map (each table numbered from 0 in declaration order unless loaded):</source>
        <translation>Mappa (ogni tabella numerata da 0 nell&apos;ordine di dichiarazione, salvo se caricata):</translation>
    </message>
    <message>
        <source>Load Modbus Map</source>
        <translation>Carica mappa Modbus</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>File CSV (*.csv)</translation>
    </message>
    <message>
        <source>Save Modbus Map</source>
        <translation>Salva mappa Modbus</translation>
    </message>
    <message>
        <source>Line %1, column %2: %3</source>
        <translation>Riga %1, colonna %2: %3</translation>
    </message>
    <message>
        <source>%1 cannot be used:</source>
        <translation>%1 non può essere usato:</translation>
    </message>
    <message>
        <source>%1 could not be saved: %2</source>
        <translation>%1 non è stato possibile salvarlo: %2</translation>
    </message>
</context>
<context>
    <name>editor::ModbusConnection</name>
    <message>
        <source>The simulation could not start.</source>
        <translation>La simulazione non è potuta partire.</translation>
    </message>
    <message>
        <source>Modbus server on %1, unit %2, clients connected: %3</source>
        <translation>Server Modbus su %1, unità %2, client connessi: %3</translation>
    </message>
    <message>
        <source>Modbus client of %1: connected</source>
        <translation>Client Modbus di %1: connesso</translation>
    </message>
    <message>
        <source>Modbus client of %1: connecting</source>
        <translation>Client Modbus di %1: connessione in corso</translation>
    </message>
    <message>
        <source>Modbus client of %1: not connected, trying again</source>
        <translation>Client Modbus di %1: non connesso, nuovo tentativo</translation>
    </message>
    <message>
        <source>Set by the twin: %1</source>
        <translation>Impostato dal gemello: %1</translation>
    </message>
    <message>
        <source>Errors: %1, the last: %2</source>
        <translation>Errori: %1, l&apos;ultimo: %2</translation>
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
        <translation>Impostazioni del modello</translation>
    </message>
    <message>
        <source>The project name written into the exported PLCopen XML</source>
        <translation>Il nome del progetto scritto nel PLCopen XML esportato</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>The period of the cyclic PLC task that runs GEMMA</source>
        <translation>Il periodo del task ciclico del PLC che esegue GEMMA</translation>
    </message>
    <message>
        <source>The flavour of the generated Structured Text and its preview</source>
        <translation>La variante del Testo strutturato generato e della sua anteprima</translation>
    </message>
    <message>
        <source>Use the cycle time and dialect for &amp;new models</source>
        <translation>Usa tempo di ciclo e dialetto per i nuovi &amp;modelli</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nome:</translation>
    </message>
    <message>
        <source>PLC &amp;cycle time:</source>
        <translation>Tempo di &amp;ciclo PLC:</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialetto:</translation>
    </message>
    <message>
        <source>Change model settings</source>
        <translation>Modifica le impostazioni del modello</translation>
    </message>
    <message>
        <source>One evolution per scan</source>
        <translation>Un&apos;evoluzione per ciclo</translation>
    </message>
    <message>
        <source>Until stable</source>
        <translation>Fino alla stabilità</translation>
    </message>
    <message>
        <source>How a nested GRAFCET evolves in one call of its function block</source>
        <translation>Come evolve un GRAFCET annidato in una chiamata del suo blocco funzione</translation>
    </message>
    <message>
        <source>&amp;Evolution rule:</source>
        <translation>Regola di &amp;evoluzione:</translation>
    </message>
    <message>
        <source>Each scan repeats evolutions until no transition can fire (IEC 60848&apos;s search for stability), at most one more than the GRAFCET has transitions; if the last one still fires, the function block reports Unstable.</source>
        <translation>Ogni ciclo ripete le evoluzioni finché nessuna transizione può scattare (la ricerca della stabilità della IEC 60848), al massimo una in più delle transizioni del GRAFCET; se l&apos;ultima scatta ancora, il blocco funzione segnala Unstable.</translation>
    </message>
    <message>
        <source>Each scan fires the transitions enabled at its start once, as SFC runtimes such as CODESYS do.</source>
        <translation>Ogni ciclo fa scattare una volta le transizioni abilitate al suo inizio, come fanno i runtime SFC quali CODESYS.</translation>
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
        <translation>La guida GEMMA (procedure di arresto, di funzionamento e di guasto) con un GRAFCET annidato in ogni macro-passo: il metodo GEMMA-GRAFCET.</translation>
    </message>
    <message>
        <source>PackML, 2015 edition</source>
        <translation>PackML, edizione 2015</translation>
    </message>
    <message>
        <source>The ISA-TR88.00.02-2015 state machine with unit modes: Production, Maintenance and Manual, a GRAFCET in each acting state.</source>
        <translation>La macchina a stati ISA-TR88.00.02-2015 con i modi di unità: Production, Maintenance e Manual, un GRAFCET in ogni stato attivo.</translation>
    </message>
    <message>
        <source>PackML, 2022 edition</source>
        <translation>PackML, edizione 2022</translation>
    </message>
    <message>
        <source>The ISA-TR88.00.02-2022 state machine: as 2015, with the Complete command that ends Execute.</source>
        <translation>La macchina a stati ISA-TR88.00.02-2022: come la 2015, con il comando Complete che termina Execute.</translation>
    </message>
    <message>
        <source>New Model</source>
        <translation>Nuovo modello</translation>
    </message>
    <message>
        <source>Which chart does the new model fill in?</source>
        <translation>Quale diagramma compila il nuovo modello?</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartContextMenu</name>
    <message>
        <source>&amp;Open GRAFCET</source>
        <translation>&amp;Apri il GRAFCET</translation>
    </message>
    <message>
        <source>&amp;Choose Its GRAFCET…</source>
        <translation>&amp;Scegli il suo GRAFCET…</translation>
    </message>
    <message>
        <source>Its own GRAFCET in this mode, the one of another mode, or none</source>
        <translation>Il proprio GRAFCET in questo modo, quello di un altro modo, o nessuno</translation>
    </message>
    <message>
        <source>Edit the %1 &amp;Condition…</source>
        <translation>Modifica la &amp;condizione di %1…</translation>
    </message>
    <message>
        <source>Show in &amp;Mode</source>
        <translation>Mostra nel &amp;modo</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartTexts</name>
    <message>
        <source>Disabled in mode %1: never active there.</source>
        <extracomment>%1: the unit mode the chart shows (&quot;3 Manual&quot;)</extracomment>
        <translation>Disattivato nel modo %1: mai attivo in esso.</translation>
    </message>
    <message>
        <source>Runs its own nested GRAFCET in this mode.</source>
        <translation>Esegue il proprio GRAFCET annidato in questo modo.</translation>
    </message>
    <message>
        <source>Runs the nested GRAFCET of mode %1 for this state.</source>
        <extracomment>%1: the number of the unit mode whose GRAFCET runs</extracomment>
        <translation>Esegue il GRAFCET annidato del modo %1 per questo stato.</translation>
    </message>
    <message>
        <source>No nested GRAFCET in this mode: it waits for a command.</source>
        <translation>Nessun GRAFCET annidato in questo modo: attende un comando.</translation>
    </message>
    <message>
        <source>No nested GRAFCET in this mode: it completes at once.</source>
        <translation>Nessun GRAFCET annidato in questo modo: si completa subito.</translation>
    </message>
    <message>
        <source>SC (State Complete): %1 has done its work.</source>
        <extracomment>%1: a PackML state (&quot;Starting&quot;)</extracomment>
        <translation>SC (State Complete): %1 ha terminato il suo lavoro.</translation>
    </message>
    <message>
        <source>Optional: exists only under an option of Model Settings.</source>
        <translation>Facoltativa: esiste solo con un&apos;opzione delle impostazioni del modello.</translation>
    </message>
    <message>
        <source>In mode %1, %2 is disabled: this transition leads to %3.</source>
        <extracomment>%1: the unit mode (&quot;3 Manual&quot;), %2: the disabled state, %3: where the transition leads instead</extracomment>
        <translation>Nel modo %1, %2 è disattivato: questa transizione porta a %3.</translation>
    </message>
    <message>
        <source>Accepted by every state in the Abort frame, before their own transitions.</source>
        <translation>Accettata da ogni stato del riquadro Abort, prima delle loro transizioni.</translation>
    </message>
    <message>
        <source>Accepted by every state in the Stop frame, before their own transitions.</source>
        <translation>Accettata da ogni stato del riquadro Stop, prima delle loro transizioni.</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Condizione:</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartView</name>
    <message>
        <source>Unit &amp;mode:</source>
        <translation>&amp;Modo dell&apos;unità:</translation>
    </message>
    <message>
        <source>The unit mode the chart shows: its disabled states greyed, its skipped transitions labelled with where they lead</source>
        <translation>Il modo dell&apos;unità mostrato dal diagramma: i suoi stati disattivati in grigio, le transizioni saltate etichettate con la loro destinazione</translation>
    </message>
</context>
<context>
    <name>editor::PackmlCommandsDock</name>
    <message>
        <source>Commands</source>
        <translation>Comandi</translation>
    </message>
    <message>
        <source>Commands belong to PackML models: this model follows GEMMA.</source>
        <translation>I comandi riguardano i modelli PackML: questo modello segue il GEMMA.</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>a PackML command&apos;s row: its PackTags number and name, &quot;4 Hold&quot;</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Condizione:</translation>
    </message>
    <message>
        <source>e.g. %1, or FALSE for a command given only through CntrlCmd</source>
        <translation>ad es. %1, o FALSE per un comando dato solo tramite CntrlCmd</translation>
    </message>
    <message>
        <source>Issues the command at its rising edge. Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND, XOR, OR, comparisons.
Ctrl+Space completes a variable name.</source>
        <translation>Dà il comando sul suo fronte di salita. Testo strutturato: variabili dichiarate, numeri, TRUE, FALSE, NOT, AND, XOR, OR, confronti.
Ctrl+Spazio completa un nome di variabile.</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Commento:</translation>
    </message>
    <message>
        <source>Where the command comes from on this machine</source>
        <translation>Da dove viene il comando su questa macchina</translation>
    </message>
</context>
<context>
    <name>editor::PackmlModeForm</name>
    <message>
        <source>Name:</source>
        <translation>Nome:</translation>
    </message>
    <message>
        <source>User modes (4 to 31) take an IEC identifier that no other mode has and the generated code does not use; it becomes part of function block names.
Modes 1 to 3 are Production, Maintenance and Manual.</source>
        <translation>I modi utente (da 4 a 31) hanno un identificatore IEC che nessun altro modo ha e che il codice generato non usa; entra nei nomi dei blocchi funzione.
I modi da 1 a 3 sono Production, Maintenance e Manual.</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Commento:</translation>
    </message>
    <message>
        <source>What the unit does in this mode</source>
        <translation>Cosa fa l&apos;unità in questo modo</translation>
    </message>
    <message>
        <source>Request condition:</source>
        <translation>Condizione di richiesta:</translation>
    </message>
    <message>
        <source>None: requested through UnitMode only (e.g. KeyManual)</source>
        <translation>Nessuna: richiesto solo tramite UnitMode (ad es. KeyManual)</translation>
    </message>
    <message>
        <source>Requests this mode at its rising edge, as a rising edge of UnitModeChangeRequest with UnitMode set to its number does.</source>
        <translation>Richiede questo modo sul suo fronte di salita, come fa un fronte di salita di UnitModeChangeRequest con UnitMode al suo numero.</translation>
    </message>
    <message>
        <source>Disabled states</source>
        <translation>Stati disattivati</translation>
    </message>
    <message>
        <source>Stopped, Idle, Execute and Aborted are never disabled. Disabling Held, Suspended or Complete disables the acting states of its loop; enabling one of those enables it again.</source>
        <translation>Stopped, Idle, Execute e Aborted non sono mai disattivati. Disattivare Held, Suspended o Complete disattiva gli stati attivi del suo ciclo; attivarne uno lo riattiva.</translation>
    </message>
    <message>
        <source>Mode change allowed in</source>
        <translation>Cambio di modo permesso in</translation>
    </message>
    <message>
        <source>A change to or from this mode is granted in a state that both modes list and the requested mode enables.</source>
        <translation>Un cambio verso o da questo modo è concesso in uno stato che entrambi i modi elencano e che il modo richiesto attiva.</translation>
    </message>
    <message>
        <source>%1 is disabled in this mode: no change can be granted there.</source>
        <translation>%1 è disattivato in questo modo: lì non può essere concesso alcun cambio.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlModesDock</name>
    <message>
        <source>Modes</source>
        <translation>Modi</translation>
    </message>
    <message>
        <source>Unit modes belong to PackML models: this model follows GEMMA.</source>
        <translation>I modi dell&apos;unità riguardano i modelli PackML: questo modello segue il GEMMA.</translation>
    </message>
    <message>
        <source>The number of the next user mode (PackTags UnitMode)</source>
        <translation>Il numero del prossimo modo utente (PackTags UnitMode)</translation>
    </message>
    <message>
        <source>&amp;Add Mode</source>
        <translation>&amp;Aggiungi modo</translation>
    </message>
    <message>
        <source>Adds a user mode with this number: every state enabled, mode changes in Stopped, Idle and Aborted</source>
        <translation>Aggiunge un modo utente con questo numero: tutti gli stati attivi, cambi di modo in Stopped, Idle e Aborted</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Rimuovi</translation>
    </message>
    <message>
        <source>&amp;Initial mode:</source>
        <translation>Modo &amp;iniziale:</translation>
    </message>
    <message>
        <source>The mode the unit is in at power-up</source>
        <translation>Il modo dell&apos;unità all&apos;accensione</translation>
    </message>
    <message>
        <source>Production is the mode every unit has</source>
        <translation>Production è il modo che ogni unità ha</translation>
    </message>
    <message>
        <source>Removes the mode with its GRAFCETs</source>
        <translation>Rimuove il modo con i suoi GRAFCET</translation>
    </message>
</context>
<context>
    <name>editor::PackmlSettingsWidget</name>
    <message>
        <source>&amp;Hold accepted in Suspended</source>
        <translation>&amp;Hold accettato in Suspended</translation>
    </message>
    <message>
        <source>Suspended → Holding on Hold, an optional transition of the 2015 model and a standard one of 2022</source>
        <translation>Suspended → Holding su Hold, una transizione facoltativa del modello 2015 e standard nel 2022</translation>
    </message>
    <message>
        <source>C&amp;omplete accepted in Suspended and Held</source>
        <translation>C&amp;omplete accettato in Suspended e Held</translation>
    </message>
    <message>
        <source>Suspended and Held → Completing on the Complete command (2022 edition only)</source>
        <translation>Suspended e Held → Completing sul comando Complete (solo edizione 2022)</translation>
    </message>
    <message>
        <source>The state at power-up: Stopped as usual, Aborted for a unit that must be cleared after a power loss, Idle for one with nothing to reset</source>
        <translation>Lo stato all&apos;accensione: Stopped di solito, Aborted per un&apos;unità da ripristinare dopo una mancanza di corrente, Idle per una senza nulla da reimpostare</translation>
    </message>
    <message>
        <source>PackML &amp;edition:</source>
        <translation>&amp;Edizione PackML:</translation>
    </message>
    <message>
        <source>Initial &amp;state:</source>
        <translation>&amp;Stato iniziale:</translation>
    </message>
    <message>
        <source>2022: Execute is left on the Complete command, which a new model conditions on Cmd_Complete; its State Complete leads nowhere.</source>
        <translation>2022: da Execute si esce con il comando Complete, che un nuovo modello condiziona a Cmd_Complete; il suo State Complete non porta da nessuna parte.</translation>
    </message>
    <message>
        <source>2015: Execute&apos;s State Complete leads to Completing; there is no Complete command.</source>
        <translation>2015: il State Complete di Execute porta a Completing; non c&apos;è il comando Complete.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlSimulationDock</name>
    <message>
        <source>PackML Simulation</source>
        <translation>Simulazione PackML</translation>
    </message>
    <message>
        <source>Start Simulation</source>
        <translation>Avvia la simulazione</translation>
    </message>
    <message>
        <source>Run or pause the scans</source>
        <translation>Esegui o sospendi i cicli</translation>
    </message>
    <message>
        <source>Single scan</source>
        <translation>Ciclo singolo</translation>
    </message>
    <message>
        <source>Step back: show the scan before</source>
        <translation>Indietro: mostra il ciclo precedente</translation>
    </message>
    <message>
        <source>Step forward: show the scan after</source>
        <translation>Avanti: mostra il ciclo successivo</translation>
    </message>
    <message>
        <source>Reset: the initial state and mode, inputs at their defaults</source>
        <translation>Reimposta: lo stato e il modo iniziali, gli ingressi ai valori predefiniti</translation>
    </message>
    <message>
        <source>End the simulation</source>
        <translation>Termina la simulazione</translation>
    </message>
    <message>
        <source>Scans/s:</source>
        <translation>Cicli/s:</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unità</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>Traccia</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Scenario</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Comandi</translation>
    </message>
    <message>
        <source>Unit mode</source>
        <translation>Modo dell&apos;unità</translation>
    </message>
    <message>
        <source>Pick a mode to request it: the mode manager grants it or says why not</source>
        <translation>Scegli un modo per richiederlo: il gestore dei modi lo concede o dice perché no</translation>
    </message>
    <message>
        <source>Function block</source>
        <translation>Blocco funzione</translation>
    </message>
    <message>
        <source>SC from the skeleton</source>
        <extracomment>the State Complete of a state without nested GRAFCET: as the generated skeleton sets it</extracomment>
        <translation>SC dallo scheletro</translation>
    </message>
    <message>
        <source>SC = TRUE (by hand)</source>
        <translation>SC = TRUE (a mano)</translation>
    </message>
    <message>
        <source>SC = FALSE (by hand)</source>
        <translation>SC = FALSE (a mano)</translation>
    </message>
    <message>
        <source>The State Complete of a state without nested GRAFCET, set by hand to hold an acting state or to complete Execute</source>
        <translation>Lo State Complete di uno stato senza GRAFCET annidato, impostato a mano per trattenere uno stato attivo o completare Execute</translation>
    </message>
    <message>
        <source>Replay Scenario…</source>
        <translation>Riproduci uno scenario…</translation>
    </message>
    <message>
        <source>Start the simulation to play the unit&apos;s commands and modes.</source>
        <translation>Avvia la simulazione per eseguire i comandi e i modi dell&apos;unità.</translation>
    </message>
    <message>
        <source>Scan %1: %2 in %3</source>
        <extracomment>%1: a scan number, %2: a PackML state (Execute), %3: a unit mode (Production)</extracomment>
        <translation>Ciclo %1: %2 in %3</translation>
    </message>
    <message>
        <source>%1 (history; the latest scan is %2)</source>
        <extracomment>%1: a status, %2: the latest scan</extracomment>
        <translation>%1 (cronologia; l&apos;ultimo ciclo è %2)</translation>
    </message>
    <message>
        <source>%1 is accepted in %2</source>
        <translation>%1 è accettato in %2</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2: pressing it shows why</source>
        <translation>%1 non è accettato in %2: premerlo mostra perché</translation>
    </message>
    <message>
        <source>%1: requested, read by the next scan</source>
        <translation>%1: richiesto, letto dal prossimo ciclo</translation>
    </message>
    <message>
        <source>%1 is a wait state: no function block runs in it</source>
        <translation>%1 è uno stato di attesa: in esso non viene eseguito alcun blocco funzione</translation>
    </message>
    <message>
        <source>%1: active steps %2, Complete = %3</source>
        <extracomment>%1: a function block instance (Production_Execute), %2: step numbers, %3: TRUE or FALSE</extracomment>
        <translation>%1: passi attivi %2, Complete = %3</translation>
    </message>
    <message>
        <source>%1 runs no GRAFCET: Complete = %2</source>
        <translation>%1 non esegue alcun GRAFCET: Complete = %2</translation>
    </message>
    <message>
        <source>Replaying %1: scan %2 of %3</source>
        <extracomment>%1: a scenario file, %2: the scan shown, %3: its last scan</extracomment>
        <translation>Riproduzione di %1: ciclo %2 di %3</translation>
    </message>
    <message>
        <source>%1 passed: all %2 expectation(s) met</source>
        <translation>%1 superato: tutte le %2 attese soddisfatte</translation>
    </message>
    <message>
        <source>%1 failed: %2 of %3 expectation(s) did not hold</source>
        <translation>%1 non superato: %2 di %3 attese non soddisfatte</translation>
    </message>
    <message>
        <source>Cannot replay %1:
%2</source>
        <translation>Impossibile riprodurre %1:
%2</translation>
    </message>
    <message>
        <source>Replay Scenario</source>
        <translation>Riproduci uno scenario</translation>
    </message>
    <message>
        <source>Scenarios (*.scenario *.txt);;All files (*)</source>
        <translation>Scenari (*.scenario *.txt);;Tutti i file (*)</translation>
    </message>
</context>
<context>
    <name>editor::PackmlStateDock</name>
    <message>
        <source>State</source>
        <translation>Stato</translation>
    </message>
    <message>
        <source>Select a state in the PackML chart to see what it means and what runs in it.</source>
        <translation>Selezionare uno stato nel diagramma PackML per vedere cosa significa e cosa vi si esegue.</translation>
    </message>
    <message>
        <source>Nested GRAFCET per mode</source>
        <translation>GRAFCET annidato per modo</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>a PackML state&apos;s title: its PackTags number and name, &quot;6 Execute&quot;</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Own: a nested GRAFCET for this mode; Same as: the one of another mode; None: the state&apos;s skeleton (%1).</source>
        <translation>Proprio: un GRAFCET annidato per questo modo; Come: quello di un altro modo; Nessuno: lo scheletro dello stato (%1).</translation>
    </message>
    <message>
        <source>Execute waits for a command</source>
        <translation>Execute attende un comando</translation>
    </message>
    <message>
        <source>the state completes at once</source>
        <translation>lo stato si completa subito</translation>
    </message>
    <message>
        <source>A wait state runs no GRAFCET.</source>
        <translation>Uno stato di attesa non esegue alcun GRAFCET.</translation>
    </message>
    <message>
        <source>Open GRAFCET</source>
        <translation>Apri GRAFCET</translation>
    </message>
    <message>
        <source>None (skeleton)</source>
        <translation>Nessuno (scheletro)</translation>
    </message>
    <message>
        <source>Own GRAFCET</source>
        <translation>GRAFCET proprio</translation>
    </message>
    <message>
        <source>Same as %1</source>
        <translation>Come %1</translation>
    </message>
    <message>
        <source>Same as mode %1 (no GRAFCET there)</source>
        <translation>Come il modo %1 (lì nessun GRAFCET)</translation>
    </message>
    <message>
        <source>%1 is disabled in this mode: nothing runs there.</source>
        <translation>%1 è disattivato in questo modo: lì non si esegue nulla.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlTraceModel</name>
    <message>
        <source>mode %1 → %2</source>
        <extracomment>a unit mode change in one scan: from, to</extracomment>
        <translation>modo %1 → %2</translation>
    </message>
    <message>
        <source>Execute resumed</source>
        <translation>Execute ripreso</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Stato</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <source>Fired</source>
        <translation>Superata</translation>
    </message>
    <message>
        <source>Dropped</source>
        <translation>Scartati</translation>
    </message>
</context>
<context>
    <name>editor::PackmlVariablesPanel</name>
    <message>
        <source>Inputs</source>
        <translation>Ingressi</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Uscite</translation>
    </message>
</context>
<context>
    <name>editor::ProblemCounter</name>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n errore</numerusform>
            <numerusform>%n errori</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n avviso</numerusform>
            <numerusform>%n avvisi</numerusform>
        </translation>
    </message>
    <message>
        <source>Show the Problems panel</source>
        <translation>Mostra il pannello Problemi</translation>
    </message>
    <message>
        <source>No problems</source>
        <translation>Nessun problema</translation>
    </message>
    <message numerus="yes">
        <source>Verification (outdated): %n finding(s)</source>
        <extracomment>the verification&apos;s findings after the checks&apos; problems in the status bar</extracomment>
        <translation>
            <numerusform>Verifica (non aggiornata): %n risultato</numerusform>
            <numerusform>Verifica (non aggiornata): %n risultati</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Verification: %n finding(s)</source>
        <translation>
            <numerusform>Verifica: %n risultato</numerusform>
            <numerusform>Verifica: %n risultati</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::ProblemsDock</name>
    <message>
        <source>Model</source>
        <translation>Modello</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Problemi</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Codice</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Messaggio</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copia</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>1 errore</translation>
    </message>
    <message numerus="yes">
        <source>%n errors</source>
        <translation>
            <numerusform>%n errore</numerusform>
            <numerusform>%n errori</numerusform>
        </translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 avviso</translation>
    </message>
    <message numerus="yes">
        <source>%n warnings</source>
        <translation>
            <numerusform>%n avviso</numerusform>
            <numerusform>%n avvisi</numerusform>
        </translation>
    </message>
    <message>
        <source>1 info</source>
        <translation>1 info</translation>
    </message>
    <message numerus="yes">
        <source>%n infos</source>
        <translation>
            <numerusform>%n info</numerusform>
            <numerusform>%n info</numerusform>
        </translation>
    </message>
    <message>
        <source>Show or hide the errors</source>
        <translation>Mostra o nascondi gli errori</translation>
    </message>
    <message>
        <source>Show or hide the warnings</source>
        <translation>Mostra o nascondi gli avvisi</translation>
    </message>
    <message>
        <source>Show or hide the information messages</source>
        <translation>Mostra o nascondi i messaggi informativi</translation>
    </message>
    <message>
        <source>Checks (%1)</source>
        <translation>Controlli (%1)</translation>
    </message>
    <message>
        <source>Verification</source>
        <translation>Verifica</translation>
    </message>
    <message>
        <source>Verification (outdated)</source>
        <translation>Verifica (superata)</translation>
    </message>
    <message>
        <source>Verification (%1)</source>
        <translation>Verifica (%1)</translation>
    </message>
    <message>
        <source>%1 step %2</source>
        <extracomment>A step of the nested GRAFCET of a GEMMA step: &quot;F1 step 3&quot;</extracomment>
        <translation>%1 tappa %2</translation>
    </message>
    <message>
        <source>%1 T%2</source>
        <extracomment>A transition of the nested GRAFCET of a GEMMA step: &quot;F1 T2&quot;</extracomment>
        <translation>%1 T%2</translation>
    </message>
    <message>
        <source>%1 GRAFCET</source>
        <extracomment>The row that holds the problems of a GEMMA step&apos;s nested GRAFCET: &quot;F1 GRAFCET&quot;</extracomment>
        <translation>GRAFCET di %1</translation>
    </message>
    <message>
        <source>Nested GRAFCET of %1: 1 problem</source>
        <translation>GRAFCET annidato di %1: 1 problema</translation>
    </message>
    <message numerus="yes">
        <source>Nested GRAFCET of %1: %n problems</source>
        <translation>
            <numerusform>GRAFCET annidato di %1: %n problema</numerusform>
            <numerusform>GRAFCET annidato di %1: %n problemi</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>machine component %1</source>
        <extracomment>A component of the virtual machine: &quot;machine component Clamp&quot;</extracomment>
        <translation>componente macchina %1</translation>
    </message>
</context>
<context>
    <name>editor::PropertiesPanel</name>
    <message>
        <source>Properties</source>
        <translation>Proprietà</translation>
    </message>
    <message>
        <source>Add Property</source>
        <translation>Aggiungi proprietà</translation>
    </message>
    <message>
        <source>Add a property after the current one (Insert)</source>
        <translation>Aggiungi una proprietà dopo quella corrente (Ins)</translation>
    </message>
    <message>
        <source>Remove Property</source>
        <translation>Rimuovi proprietà</translation>
    </message>
    <message>
        <source>Remove the current property (Delete)</source>
        <translation>Rimuovi la proprietà corrente (Canc)</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Sposta su</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Sposta giù</translation>
    </message>
    <message>
        <source>&amp;Property:</source>
        <translation>&amp;Proprietà:</translation>
    </message>
    <message>
        <source>never A_Plus AND A_Minus</source>
        <translation>never A_Plus AND A_Minus</translation>
    </message>
    <message>
        <source>Write never P or always P, where P is a condition over the variables that may also use in S (the GEMMA step S is active), S.Xn (step n of S&apos;s nested GRAFCET is active) and a -&gt; b (if a then b). Verify (F7) proves or refutes each one.</source>
        <translation>Scrivi never P o always P, dove P è una condizione sulle variabili che può usare anche in S (la tappa GEMMA S è attiva), S.Xn (la tappa n del GRAFCET annidato di S è attiva) e a -&gt; b (se a allora b). Verifica (F7) dimostra o confuta ciascuna.</translation>
    </message>
</context>
<context>
    <name>editor::PropertiesTableModel</name>
    <message>
        <source>Property</source>
        <translation>Proprietà</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Commento</translation>
    </message>
</context>
<context>
    <name>editor::RecentFiles</name>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Apri re&amp;centi</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>&amp;Svuota il menu</translation>
    </message>
</context>
<context>
    <name>editor::SimulationDock</name>
    <message>
        <source>fires in the next scan</source>
        <translation>scatta al prossimo ciclo</translation>
    </message>
    <message>
        <source>condition FALSE</source>
        <translation>condizione FALSE</translation>
    </message>
    <message>
        <source>waits for Complete</source>
        <translation>attende Complete</translation>
    </message>
    <message>
        <source>preempted by %1</source>
        <translation>preceduta da %1</translation>
    </message>
    <message>
        <source>condition unusable (always FALSE)</source>
        <translation>condizione inutilizzabile (sempre FALSE)</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulazione</translation>
    </message>
    <message>
        <source>The simulation runs the model scan by scan, as the generated program runs on the PLC: play the inputs, watch the active step and see why each transition fires or not. Editing is locked while it runs.</source>
        <translation>La simulazione esegue il modello ciclo per ciclo, come il programma generato viene eseguito sul PLC: agisci sugli ingressi, osserva la tappa attiva e scopri perché ogni transizione scatta o no. La modifica è bloccata durante la simulazione.</translation>
    </message>
    <message>
        <source>Start Simulation</source>
        <translation>Avvia la simulazione</translation>
    </message>
    <message>
        <source>Explanation</source>
        <translation>Spiegazione</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>Traccia</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Scenario</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Esegui</translation>
    </message>
    <message>
        <source>Run scans at the chosen speed; press again to pause</source>
        <translation>Esegue i cicli alla velocità scelta; premi di nuovo per mettere in pausa</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <source>Run a single scan</source>
        <translation>Esegue un solo ciclo</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reimposta</translation>
    </message>
    <message>
        <source>Back to the initial step, the inputs to their defaults; clears the trace</source>
        <translation>Torna alla tappa iniziale, gli ingressi ai valori iniziali; cancella la traccia</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Termina</translation>
    </message>
    <message>
        <source>End the simulation and unlock editing</source>
        <translation>Termina la simulazione e sblocca la modifica</translation>
    </message>
    <message>
        <source>&amp;Speed:</source>
        <translation>&amp;Velocità:</translation>
    </message>
    <message>
        <source> scans/s</source>
        <translation> cicli/s</translation>
    </message>
    <message>
        <source>Scans per second (the model&apos;s cycle time only sets the simulated time)</source>
        <translation>Cicli al secondo (il tempo di ciclo del modello determina solo il tempo simulato)</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transizione</translation>
    </message>
    <message>
        <source>Next scan</source>
        <translation>Prossimo ciclo</translation>
    </message>
    <message>
        <source>&amp;Record as Scenario…</source>
        <translation>&amp;Registra come scenario…</translation>
    </message>
    <message>
        <source>Re&amp;play Scenario…</source>
        <translation>Ri&amp;produci uno scenario…</translation>
    </message>
    <message>
        <source>Run a scenario file from the initial step and check its expectations</source>
        <translation>Esegue un file di scenario dalla tappa iniziale e ne verifica le attese</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Ingressi</translation>
    </message>
    <message>
        <source>The model declares no variables.</source>
        <translation>Il modello non dichiara variabili.</translation>
    </message>
    <message>
        <source>Complete of nested steps</source>
        <translation>Complete delle tappe con comportamento interno</translation>
    </message>
    <message>
        <source>Automatic: the skeleton function block completes at once. Manual: you play the nested behaviour and set Complete yourself.</source>
        <translation>Automatico: il blocco funzione scheletro si completa subito. Manuale: simuli tu il comportamento interno e imposti Complete.</translation>
    </message>
    <message>
        <source>Switch %1 between TRUE and FALSE</source>
        <translation>Commuta %1 tra TRUE e FALSE</translation>
    </message>
    <message>
        <source>Press</source>
        <translation>Premi</translation>
    </message>
    <message>
        <source>TRUE while held down, like a push button (for at least one scan)</source>
        <translation>TRUE finché è premuto, come un pulsante (almeno per un ciclo)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatico</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>Manuale</translation>
    </message>
    <message>
        <source>How %1&apos;s function block sets Complete</source>
        <translation>Come il blocco funzione di %1 imposta Complete</translation>
    </message>
    <message>
        <source>Complete</source>
        <translation>Complete</translation>
    </message>
    <message>
        <source>The value the nested behaviour gives Complete (manual mode)</source>
        <translation>Il valore che il comportamento interno dà a Complete (modalità manuale)</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>Scan %1 · %2 s</source>
        <translation>Ciclo %1 · %2 s</translation>
    </message>
    <message>
        <source>%1.Complete = %2 (after the last call of its function block)</source>
        <translation>%1.Complete = %2 (dopo l&apos;ultima chiamata del suo blocco funzione)</translation>
    </message>
    <message>
        <source>No visible step is active (State = %1).</source>
        <translation>Nessuna tappa visibile è attiva (State = %1).</translation>
    </message>
    <message>
        <source>Active step: &lt;b&gt;%1&lt;/b&gt; %2 · Entry = %3</source>
        <translation>Tappa attiva: &lt;b&gt;%1&lt;/b&gt; %2 · Entry = %3</translation>
    </message>
    <message>
        <source>%1 (family)</source>
        <translation>%1 (famiglia)</translation>
    </message>
    <message>
        <source>The active step has no transition to evaluate.</source>
        <translation>La tappa attiva non ha transizioni da valutare.</translation>
    </message>
    <message>
        <source>Record this session as a scenario file, or replay one.</source>
        <translation>Registra questa sessione come file di scenario, o riproducine uno.</translation>
    </message>
    <message>
        <source>%1: every expectation met (%2).</source>
        <translation>%1: tutte le attese soddisfatte (%2).</translation>
    </message>
    <message>
        <source>%1: %2 of %3 expectations failed.</source>
        <translation>%1: %2 attese su %3 non soddisfatte.</translation>
    </message>
    <message>
        <source>Line %1: %2</source>
        <translation>Riga %1: %2</translation>
    </message>
    <message>
        <source>session</source>
        <translation>sessione</translation>
    </message>
    <message>
        <source>Record as Scenario</source>
        <translation>Registra come scenario</translation>
    </message>
    <message>
        <source>Simulation scenarios (*.scenario *.txt);;All files (*)</source>
        <translation>Scenari di simulazione (*.scenario *.txt);;Tutti i file (*)</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>Impossibile scrivere %1.</translation>
    </message>
    <message>
        <source>Recorded %1 scans to %2.</source>
        <translation>%1 cicli registrati in %2.</translation>
    </message>
    <message>
        <source>Replay Scenario</source>
        <translation>Riproduci uno scenario</translation>
    </message>
    <message>
        <source>Could not replay %1.</source>
        <translation>Impossibile riprodurre %1.</translation>
    </message>
    <message>
        <source>upstream step not active</source>
        <translation>tappa a monte non attiva</translation>
    </message>
    <message>
        <source>receptivity FALSE</source>
        <translation>ricettività FALSE</translation>
    </message>
    <message>
        <source>receptivity unusable (always FALSE)</source>
        <translation>ricettività inutilizzabile (sempre FALSE)</translation>
    </message>
    <message>
        <source>not called</source>
        <translation>non chiamato</translation>
    </message>
    <message>
        <source>Save this session since the last reset as a scenario file: the inputs of each scan, and expectations for every transition that fired, every output that changed and every nested situation that changed</source>
        <translation>Salva questa sessione dall&apos;ultimo ripristino come file di scenario: gli ingressi di ogni ciclo e attese per ogni transizione scattata, ogni uscita cambiata e ogni situazione cambiata di un GRAFCET annidato</translation>
    </message>
    <message>
        <source>GRAFCET of %1: no step active</source>
        <translation>GRAFCET di %1: nessuna tappa attiva</translation>
    </message>
    <message>
        <source>GRAFCET of %1: steps %2</source>
        <translation>GRAFCET di %1: tappe %2</translation>
    </message>
    <message>
        <source>initialised again in the next scan (steps %1)</source>
        <translation>reinizializzato al prossimo ciclo (tappe %1)</translation>
    </message>
    <message>
        <source>first evolution of the next scan</source>
        <translation>prima evoluzione del prossimo ciclo</translation>
    </message>
    <message>
        <source>Until stable: the next scan&apos;s first evolution is explained; later evolutions of the same scan follow with edges FALSE.</source>
        <translation>Fino a stabilità: si spiega la prima evoluzione del prossimo ciclo; le evoluzioni successive dello stesso ciclo seguono con i fronti a FALSE.</translation>
    </message>
    <message>
        <source>One evolution per scan.</source>
        <translation>Una evoluzione per ciclo.</translation>
    </message>
    <message>
        <source>%1 (step %2): %3 ms of %4 ms</source>
        <extracomment>%1: a timer of a time-dependent receptivity; %2: its step; %3 of %4: elapsed and set time in ms</extracomment>
        <translation>%1 (tappa %2): %3 ms su %4 ms</translation>
    </message>
    <message>
        <source>Outputs: %1</source>
        <extracomment>the outputs a nested GRAFCET drives, with their values (&quot;Spindle = TRUE, Marker = FALSE&quot;)</extracomment>
        <translation>Uscite: %1</translation>
    </message>
    <message>
        <source>T%1 (%2 → %3)</source>
        <extracomment>a transition of a nested GRAFCET: its number, upstream and downstream steps</extracomment>
        <translation>T%1 (%2 → %3)</translation>
    </message>
    <message>
        <source>Outputs and internal variables</source>
        <translation>Uscite e variabili interne</translation>
    </message>
    <message>
        <source>Written by the program: %1 is not an input</source>
        <translation>Scritta dal programma: %1 non è un ingresso</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Indietro</translation>
    </message>
    <message>
        <source>Show the previous scan of the history (%1); a scan or Run from a past scan continues from it and drops the later scans</source>
        <translation>Mostra il ciclo precedente della cronologia (%1); un ciclo o Esegui da un ciclo passato riprende da lì e scarta i cicli successivi</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Avanti</translation>
    </message>
    <message>
        <source>Show the next scan of the history (%1)</source>
        <translation>Mostra il ciclo successivo della cronologia (%1)</translation>
    </message>
    <message>
        <source>Scan %1 of %2 (history) · %3 s</source>
        <extracomment>%1 of %2: the past scan shown and the latest scan run; %3: its simulated time in seconds</extracomment>
        <translation>Ciclo %1 di %2 (cronologia) · %3 s</translation>
    </message>
    <message>
        <source>Replaying %1: scan %2 of %3.</source>
        <extracomment>%1: the scenario file; %2 of %3: the scan reached and the scenario&apos;s last scan</extracomment>
        <translation>Riproduzione di %1: ciclo %2 di %3.</translation>
    </message>
    <message>
        <source>Replay of %1: paused at scan %2 of %3. Press %4 to step, or Run to play the rest.</source>
        <extracomment>%1: the scenario file; %2 of %3: the scan reached and the scenario&apos;s last scan; %4: a key (F10)</extracomment>
        <translation>Riproduzione di %1: in pausa al ciclo %2 di %3. Premi %4 per avanzare di un ciclo, o Esegui per riprodurre il resto.</translation>
    </message>
    <message>
        <source>Unstable: the GRAFCET of %1 found no stable situation in this scan; its last evolution still fired.</source>
        <extracomment>Unstable is the name of the function block&apos;s output (not translated); %1: macro-steps or enclosing steps</extracomment>
        <translation>Unstable: il GRAFCET di %1 non ha trovato una situazione stabile in questo ciclo; la sua ultima evoluzione ha ancora superato una transizione.</translation>
    </message>
    <message>
        <source>the condition of %1</source>
        <translation>la condizione di %1</translation>
    </message>
    <message>
        <source>the receptivity of T%1 of %2</source>
        <translation>la recettività di T%1 di %2</translation>
    </message>
    <message>
        <source>action %1 of step %2 of %3</source>
        <translation>l&apos;azione %1 della fase %2 di %3</translation>
    </message>
    <message>
        <source>Stopped at scan %1: integer division by zero in %2 (%3 in &apos;%4&apos;). On the PLC the task stops with a fault; Reset to run again.</source>
        <translation>Fermato al ciclo %1: divisione intera per zero in %2 (%3 in &apos;%4&apos;). Sul PLC il task si arresta con un errore; Reimposta per ripartire.</translation>
    </message>
    <message numerus="yes">
        <source>%n other transition(s): an upstream step is not active</source>
        <extracomment>the transitions of a large nested GRAFCET left out of the explanation</extracomment>
        <translation>
            <numerusform>%n altra transizione: una fase a monte non è attiva</numerusform>
            <numerusform>%n altre transizioni: una fase a monte non è attiva</numerusform>
        </translation>
    </message>
    <message>
        <source>Sensors (set by the machine)</source>
        <translation>Sensori (impostati dalla macchina)</translation>
    </message>
    <message>
        <source>Written by the machine: %1 is a sensor of %2</source>
        <translation>Scritto dalla macchina: %1 è un sensore di %2</translation>
    </message>
    <message>
        <source>It sets the machine&apos;s sensors itself: played in open loop, the machine stands still.</source>
        <translation>Imposta da sé i sensori della macchina: riprodotto ad anello aperto, la macchina resta ferma.</translation>
    </message>
    <message>
        <source>Right-click to inject a fault</source>
        <translation>Clic destro per iniettare un guasto</translation>
    </message>
</context>
<context>
    <name>editor::SimulationSession</name>
    <message>
        <source>(%1 more)</source>
        <translation>(altri %1)</translation>
    </message>
    <message>
        <source>%1 is a sensor of the machine&apos;s %2: the machine sets it</source>
        <translation>%1 è un sensore di %2 della macchina: lo imposta la macchina</translation>
    </message>
    <message>
        <source>The replay plays the machine&apos;s faults: stop it first</source>
        <translation>La riproduzione applica i guasti della macchina: fermarla prima</translation>
    </message>
    <message>
        <source>A fault needs the virtual machine running in closed loop</source>
        <translation>Un guasto richiede la macchina virtuale in anello chiuso</translation>
    </message>
</context>
<context>
    <name>editor::StPreviewDock</name>
    <message>
        <source>Structured Text</source>
        <translation>Testo strutturato (ST)</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialetto:</translation>
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
        <translation>Beremiz, OpenPLC, TwinCAT, matiec: variabili globali nella configurazione</translation>
    </message>
    <message>
        <source>CODESYS V3.5: globals in the list GVL, read as GVL.Name</source>
        <translation>CODESYS V3.5: variabili globali nella lista GVL, lette come GVL.Nome</translation>
    </message>
    <message>
        <source>The flavour of the generated code; saved with the model</source>
        <translation>La variante del codice generato; salvata con il modello</translation>
    </message>
    <message>
        <source>%1 is hidden: it generates no code.</source>
        <translation>%1 è nascosta: non genera codice.</translation>
    </message>
    <message>
        <source>This transition is not effective: it generates no code.</source>
        <translation>Questa transizione non è effettiva: non genera codice.</translation>
    </message>
    <message>
        <source>%1 generates no function block: only a visible macro-step or enclosing step does.</source>
        <translation>%1 non genera alcun blocco funzione: solo una macro-tappa o una tappa incapsulante visibile lo fa.</translation>
    </message>
    <message>
        <source>%1_FB (the nested GRAFCET of %1)</source>
        <extracomment>the function block shown: &quot;F1_FB (the nested GRAFCET of F1)&quot;</extracomment>
        <translation>%1_FB (il GRAFCET annidato di %1)</translation>
    </message>
    <message>
        <source>No enabled state runs this GRAFCET: it generates no function block.</source>
        <translation>Nessuno stato abilitato esegue questo GRAFCET: non genera alcun blocco funzionale.</translation>
    </message>
    <message>
        <source>%1 is disabled in this unit mode: the mode&apos;s state machine has no branch for it.</source>
        <translation>%1 è disabilitato in questo modo di unità: la macchina a stati del modo non ha un ramo per esso.</translation>
    </message>
</context>
<context>
    <name>editor::StartGuide</name>
    <message>
        <source>Getting started</source>
        <translation>Per iniziare</translation>
    </message>
    <message>
        <source>&lt;b&gt;Hide&lt;/b&gt; what your machine does not need: select states or transitions and press Delete (Shift+Delete shows them again).</source>
        <translation>&lt;b&gt;Nascondete&lt;/b&gt; ciò che la vostra macchina non usa: selezionate stati o transizioni e premete Canc (Maiusc+Canc li mostra di nuovo).</translation>
    </message>
    <message>
        <source>&lt;b&gt;Declare&lt;/b&gt; the buttons, sensors and actuators in the Variables panel below.</source>
        <translation>&lt;b&gt;Dichiarate&lt;/b&gt; pulsanti, sensori e attuatori nel pannello Variabili qui sotto.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Write&lt;/b&gt; each transition&apos;s condition: select the transition and press Enter. Red marks what is not finished yet.</source>
        <translation>&lt;b&gt;Scrivete&lt;/b&gt; la condizione di ogni transizione: selezionate la transizione e premete Invio. Il rosso segna ciò che non è ancora finito.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Simulate&lt;/b&gt; with F5, &lt;b&gt;verify&lt;/b&gt; with F7, then export PLCopen XML for your PLC.</source>
        <translation>&lt;b&gt;Simulate&lt;/b&gt; con F5, &lt;b&gt;verificate&lt;/b&gt; con F7, poi esportate il PLCopen XML per il vostro PLC.</translation>
    </message>
    <message>
        <source>The chart is the GEMMA sheet: the ways your machine stops (A), works (F) and fails (D), and the transitions between them.</source>
        <translation>Il diagramma è il foglio GEMMA: come la vostra macchina si ferma (A), funziona (F) e si guasta (D), e le transizioni tra questi stati.</translation>
    </message>
    <message>
        <source>Select a step or a transition to edit it here.</source>
        <translation>Selezionate una tappa o una transizione per modificarla qui.</translation>
    </message>
    <message>
        <source>Open an Example</source>
        <translation>Apri un esempio</translation>
    </message>
    <message>
        <source>A finished model to look at and simulate, opened as an untitled copy</source>
        <translation>Un modello finito da guardare e simulare, aperto come copia senza titolo</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>Guida utente</translation>
    </message>
    <message>
        <source>How to build a model step by step (F1)</source>
        <translation>Come costruire un modello passo per passo (F1)</translation>
    </message>
</context>
<context>
    <name>editor::StepDock</name>
    <message>
        <source>Step</source>
        <translation>Tappa</translation>
    </message>
    <message>
        <source>Select a step in the chart to see and edit its properties.</source>
        <translation>Seleziona una tappa nel diagramma per vederne e modificarne le proprietà.</translation>
    </message>
    <message>
        <source>Simple step: no nested behaviour.
Macro-step: its transitions wait until the nested behaviour is complete.
Enclosing step: its transitions fire whatever the nested behaviour is doing.</source>
        <translation>Tappa semplice: nessun comportamento interno.
Macro-tappa: le sue transizioni attendono che il comportamento interno sia completo.
Tappa incapsulante: le sue transizioni scattano qualunque cosa stia facendo il comportamento interno.</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Tipo:</translation>
    </message>
    <message>
        <source>&amp;Initial</source>
        <translation>&amp;Iniziale</translation>
    </message>
    <message>
        <source>&amp;Hidden</source>
        <translation>&amp;Nascosta</translation>
    </message>
    <message>
        <source>A hidden step is not part of this machine: it generates no code, and its transitions are not effective.</source>
        <translation>Una tappa nascosta non fa parte di questa macchina: non genera codice e le sue transizioni non sono effettive.</translation>
    </message>
    <message>
        <source>What this state does on this machine</source>
        <translation>Cosa fa questo stato su questa macchina</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Commento:</translation>
    </message>
    <message>
        <source>Incoming transitions</source>
        <translation>Transizioni entranti</translation>
    </message>
    <message>
        <source>Outgoing transitions, by priority</source>
        <translation>Transizioni uscenti, per priorità</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transizione</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Condizione</translation>
    </message>
    <message>
        <source>Click a transition to select it</source>
        <translation>Fai clic su una transizione per selezionarla</translation>
    </message>
    <message>
        <source>%1 · state number %2</source>
        <translation>%1 · stato numero %2</translation>
    </message>
    <message>
        <source>%1 is the initial step. There is always exactly one initial step: to change it, make another step initial.</source>
        <translation>%1 è la tappa iniziale. C&apos;è sempre esattamente una tappa iniziale: per cambiarla, rendi iniziale un&apos;altra tappa.</translation>
    </message>
    <message>
        <source>Make %1 the initial step (the PLC starts in it). The current initial step is %2.</source>
        <translation>Rendi %1 la tappa iniziale (il PLC parte da essa). La tappa iniziale attuale è %2.</translation>
    </message>
    <message>
        <source>F (family) →</source>
        <extracomment>an incoming transition: its source, an arrow</extracomment>
        <translation>F (famiglia) →</translation>
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
        <translation>Transizione di famiglia: valutata prima delle transizioni proprie di ogni stato F visibile.</translation>
    </message>
    <message>
        <source>Negated</source>
        <translation>Negata</translation>
    </message>
    <message>
        <source>Condition: %1</source>
        <translation>Condizione: %1</translation>
    </message>
    <message>
        <source>Not effective (%1): generates no code.</source>
        <translation>Non effettiva (%1): non genera codice.</translation>
    </message>
    <message>
        <source>%1 (negated)</source>
        <extracomment>a negated transition in the Step dock&apos;s lists: the entry, then the mark</extracomment>
        <translation>%1 (negata)</translation>
    </message>
    <message>
        <source>Open Nested GRAFCET</source>
        <translation>Apri il GRAFCET annidato</translation>
    </message>
    <message>
        <source>Show the nested GRAFCET of this step in a tab beside the GEMMA chart (double-click the step on the chart does the same)</source>
        <translation>Mostra il GRAFCET annidato di questa tappa in una scheda accanto al diagramma GEMMA (un doppio clic sulla tappa nel diagramma fa lo stesso)</translation>
    </message>
</context>
<context>
    <name>editor::StepItem</name>
    <message>
        <source>Simple step</source>
        <translation>Tappa semplice</translation>
    </message>
    <message>
        <source>Macro-step</source>
        <translation>Macro-tappa</translation>
    </message>
    <message>
        <source>Enclosing step</source>
        <translation>Tappa incapsulante</translation>
    </message>
    <message>
        <source>%1, initial</source>
        <translation>%1, iniziale</translation>
    </message>
    <message>
        <source>%1, hidden</source>
        <translation>%1, nascosta</translation>
    </message>
    <message numerus="yes">
        <source>Has a nested GRAFCET (%n steps)</source>
        <translation>
            <numerusform>Ha un GRAFCET annidato (%n tappa)</numerusform>
            <numerusform>Ha un GRAFCET annidato (%n tappe)</numerusform>
        </translation>
    </message>
    <message>
        <source>Its GRAFCET runs: steps %1 active</source>
        <extracomment>simulation; %1: the active steps of the nested GRAFCET (&quot;3, 5&quot;)</extracomment>
        <translation>Il suo GRAFCET evolve: tappe %1 attive</translation>
    </message>
    <message>
        <source>Its nested GRAFCET has 1 problem</source>
        <translation>Il suo GRAFCET annidato ha 1 problema</translation>
    </message>
    <message numerus="yes">
        <source>Its nested GRAFCET has %n problems</source>
        <translation>
            <numerusform>Il suo GRAFCET annidato ha %n problema</numerusform>
            <numerusform>Il suo GRAFCET annidato ha %n problemi</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::TraceTableModel</name>
    <message>
        <source>Scan</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Tappa</translation>
    </message>
    <message>
        <source>Fired</source>
        <translation>Scattata</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Entry</translation>
    </message>
    <message>
        <source>Tokens TRUE</source>
        <translation>Memorie TRUE</translation>
    </message>
    <message>
        <source>Changed inputs</source>
        <translation>Ingressi modificati</translation>
    </message>
</context>
<context>
    <name>editor::TransitionDock</name>
    <message>
        <source>Transition</source>
        <translation>Transizione</translation>
    </message>
    <message>
        <source>Select a transition in the chart to see and edit its condition.</source>
        <translation>Seleziona una transizione nel diagramma per vederne e modificarne la condizione.</translation>
    </message>
    <message>
        <source>Click a step to select it</source>
        <translation>Fai clic su una tappa per selezionarla</translation>
    </message>
    <message>
        <source>C&amp;ondition:</source>
        <translation>&amp;Condizione:</translation>
    </message>
    <message>
        <source>e.g. Start AND NOT Stop</source>
        <translation>es. Start AND NOT Stop</translation>
    </message>
    <message>
        <source>Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND (&amp;), XOR, OR, comparisons and arithmetic.
Ctrl+Space completes a variable name.</source>
        <translation>Testo strutturato: variabili dichiarate, numeri, TRUE, FALSE, NOT, AND (&amp;), XOR, OR, confronti e aritmetica.
Ctrl+Spazio completa un nome di variabile.</translation>
    </message>
    <message>
        <source>&amp;Priority:</source>
        <translation>&amp;Priorità:</translation>
    </message>
    <message>
        <source>&amp;Negated</source>
        <translation>&amp;Negata</translation>
    </message>
    <message>
        <source>Negation flips when this transition waits for the nested behaviour of its source:
a negated transition out of a macro-step ignores Complete;
a negated transition out of an enclosing step waits for Complete.</source>
        <translation>La negazione inverte l&apos;attesa di questa transizione rispetto al comportamento interno della sua tappa di origine:
una transizione negata uscente da una macro-tappa ignora Complete;
una transizione negata uscente da una tappa incapsulante attende Complete.</translation>
    </message>
    <message>
        <source>&amp;Hidden</source>
        <translation>Na&amp;scosta</translation>
    </message>
    <message>
        <source>A hidden transition is not part of this machine: it generates no code.</source>
        <translation>Una transizione nascosta non fa parte di questa macchina: non genera codice.</translation>
    </message>
    <message>
        <source>Tokens</source>
        <translation>Memorie</translation>
    </message>
    <message>
        <source>F (family)</source>
        <translation>F (famiglia)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <extracomment>a transition: source step, arrow, target step</extracomment>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Not effective (%1): generates no code.</source>
        <translation>Non effettiva (%1): non genera codice.</translation>
    </message>
    <message>
        <source>First</source>
        <translation>Prima</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Nessuna</translation>
    </message>
    <message>
        <source>The family transition is evaluated before the own transitions of every visible F state.</source>
        <translation>La transizione di famiglia è valutata prima delle transizioni proprie di ogni stato F visibile.</translation>
    </message>
    <message>
        <source>Only effective transitions have a priority: show this transition and both its steps first.</source>
        <translation>Solo le transizioni effettive hanno una priorità: mostra prima questa transizione e le sue due tappe.</translation>
    </message>
    <message>
        <source> of %1</source>
        <extracomment>after the priority in its spin box: &quot;2 of 5&quot;</extracomment>
        <translation> di %1</translation>
    </message>
    <message>
        <source>1 is evaluated first among the effective transitions out of %1; the others move to make room.</source>
        <translation>1 è valutata per prima tra le transizioni effettive uscenti da %1; le altre scalano per fare posto.</translation>
    </message>
    <message>
        <source>Negation has no effect here: family transitions never wait for Complete.</source>
        <translation>Qui la negazione non ha effetto: le transizioni di famiglia non attendono mai Complete.</translation>
    </message>
    <message>
        <source>Negation has no effect here: %1 is a simple step, and only transitions out of macro-steps and enclosing steps wait for Complete.</source>
        <translation>Qui la negazione non ha effetto: %1 è una tappa semplice, e solo le transizioni uscenti da macro-tappe e tappe incapsulanti attendono Complete.</translation>
    </message>
    <message>
        <source>Fires without waiting for the nested behaviour of macro-step %1 to complete.</source>
        <translation>Scatta senza attendere che il comportamento interno della macro-tappa %1 sia completo.</translation>
    </message>
    <message>
        <source>Waits until the nested behaviour of macro-step %1 is complete (%1.Complete). Negate it to fire at once.</source>
        <translation>Attende che il comportamento interno della macro-tappa %1 sia completo (%1.Complete). Negala per farla scattare subito.</translation>
    </message>
    <message>
        <source>Waits until the nested behaviour of enclosing step %1 is complete (%1.Complete).</source>
        <translation>Attende che il comportamento interno della tappa incapsulante %1 sia completo (%1.Complete).</translation>
    </message>
    <message>
        <source>Fires whatever the nested behaviour of enclosing step %1 is doing. Negate it to wait for %1.Complete.</source>
        <translation>Scatta qualunque cosa stia facendo il comportamento interno della tappa incapsulante %1. Negala per attendere %1.Complete.</translation>
    </message>
    <message>
        <source>Token on %1 (compared: no polarity)</source>
        <translation>Memoria su %1 (confronto: nessuna polarità)</translation>
    </message>
    <message>
        <source>Token on %1 (both NO and NC)</source>
        <translation>Memoria su %1 (sia NA sia NC)</translation>
    </message>
    <message>
        <source>Token on %1 (NC)</source>
        <translation>Memoria su %1 (NC)</translation>
    </message>
    <message>
        <source>Token on %1 (NO)</source>
        <translation>Memoria su %1 (NA)</translation>
    </message>
    <message>
        <source>A token replaces a literal %1 or NOT %1: rewrite the condition so that %1 has one polarity.</source>
        <translation>Una memoria sostituisce un letterale %1 o NOT %1: riscrivi la condizione in modo che %1 abbia una sola polarità.</translation>
    </message>
    <message>
        <source>Normally closed: remembers that %1 was FALSE while the nested behaviour of %2 was not complete.</source>
        <translation>Normalmente chiusa: ricorda che %1 era FALSE mentre il comportamento interno di %2 non era completo.</translation>
    </message>
    <message>
        <source>Normally open: remembers that %1 was TRUE while the nested behaviour of %2 was not complete.</source>
        <translation>Normalmente aperta: ricorda che %1 era TRUE mentre il comportamento interno di %2 non era completo.</translation>
    </message>
    <message>
        <source>Generated as %1_%2_%3_MEM.</source>
        <translation>Generata come %1_%2_%3_MEM.</translation>
    </message>
    <message>
        <source>Token on %1 (not a BOOL variable of the condition)</source>
        <translation>Memoria su %1 (non è una variabile BOOL della condizione)</translation>
    </message>
    <message>
        <source>Uncheck to remove this token.</source>
        <translation>Deseleziona per rimuovere questa memoria.</translation>
    </message>
    <message>
        <source>Family transitions never wait for Complete, so tokens do not apply to them.</source>
        <translation>Le transizioni di famiglia non attendono mai Complete, quindi le memorie non si applicano a esse.</translation>
    </message>
    <message>
        <source>Tokens apply to transitions out of macro-steps and enclosing steps; %1 is a simple step.</source>
        <translation>Le memorie si applicano alle transizioni uscenti da macro-tappe e tappe incapsulanti; %1 è una tappa semplice.</translation>
    </message>
    <message>
        <source>Correct the condition to choose its tokens.</source>
        <translation>Correggi la condizione per sceglierne le memorie.</translation>
    </message>
    <message>
        <source>The condition uses no BOOL variable.</source>
        <translation>La condizione non usa alcuna variabile BOOL.</translation>
    </message>
    <message>
        <source>A token keeps a short pulse of a BOOL variable that occurs while the nested behaviour of %1 is not yet complete.</source>
        <translation>Una memoria conserva un breve impulso di una variabile BOOL che si verifica mentre il comportamento interno di %1 non è ancora completo.</translation>
    </message>
</context>
<context>
    <name>editor::TransitionItem</name>
    <message>
        <source>Family transition: applies to every F state</source>
        <translation>Transizione di famiglia: si applica a ogni stato F</translation>
    </message>
    <message>
        <source>Priority %1</source>
        <translation>Priorità %1</translation>
    </message>
    <message>
        <source>Not effective (hidden)</source>
        <translation>Non effettiva (nascosta)</translation>
    </message>
    <message>
        <source>%1, negated</source>
        <translation>%1, negata</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Condizione:</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>vuota</translation>
    </message>
    <message>
        <source>Tokens: %1</source>
        <translation>Memorie: %1</translation>
    </message>
</context>
<context>
    <name>editor::UserGuide</name>
    <message>
        <source>GG Studio User Guide</source>
        <translation>Guida utente di GG Studio</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Indietro</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Avanti</translation>
    </message>
    <message>
        <source>Getting Started</source>
        <translation>Primi passi</translation>
    </message>
</context>
<context>
    <name>editor::VariablesDock</name>
    <message>
        <source>Variables</source>
        <translation>Variabili</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filtro</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Aggiungi</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Rimuovi</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplica</translation>
    </message>
    <message>
        <source>Duplicate the selected variables</source>
        <translation>Duplica le variabili selezionate</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Sposta su</translation>
    </message>
    <message>
        <source>Move the current variable up (declaration order)</source>
        <translation>Sposta in alto la variabile corrente (ordine di dichiarazione)</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Sposta giù</translation>
    </message>
    <message>
        <source>Move the current variable down (declaration order)</source>
        <translation>Sposta in basso la variabile corrente (ordine di dichiarazione)</translation>
    </message>
    <message>
        <source>Sort by Name</source>
        <translation>Ordina per nome</translation>
    </message>
    <message>
        <source>Sort the declarations by name (one undo step)</source>
        <translation>Ordina le dichiarazioni per nome (un solo passo di annullamento)</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Copia</translation>
    </message>
    <message>
        <source>Paste</source>
        <translation>Incolla</translation>
    </message>
    <message>
        <source>Variable%1</source>
        <translation>Variabile%1</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n variables</source>
        <translation>
            <numerusform>Rimuovi %n variabile</numerusform>
            <numerusform>Rimuovi %n variabili</numerusform>
        </translation>
    </message>
    <message>
        <source>Sort variables by name</source>
        <translation>Ordina le variabili per nome</translation>
    </message>
    <message>
        <source>Remove the selected variables</source>
        <translation>Rimuovi le variabili selezionate</translation>
    </message>
    <message>
        <source>Copy the selected variables as tab-separated rows</source>
        <translation>Copia le variabili selezionate come righe separate da tabulazioni</translation>
    </message>
    <message>
        <source>Show only the variables whose name, type, kind, default or comment contains this text</source>
        <translation>Mostra solo le variabili il cui nome, tipo, natura, valore iniziale o commento contiene questo testo</translation>
    </message>
    <message>
        <source>Add a BOOL variable after the current one (Insert)</source>
        <translation>Aggiungere una variabile BOOL dopo quella corrente (Ins)</translation>
    </message>
    <message>
        <source>Paste rows from a spreadsheet: name, type, default, comment and kind, in this order or in the order a first row of column titles gives</source>
        <translation>Incollare righe da un foglio di calcolo: nome, tipo, valore iniziale, commento e natura, in quest&apos;ordine o nell&apos;ordine dato da una prima riga di titoli di colonna</translation>
    </message>
</context>
<context>
    <name>editor::VariablesTableModel</name>
    <message>
        <source>No default: the PLC starts with %1.</source>
        <translation>Nessun valore iniziale: il PLC parte con %1.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a supported type: use one of %2.</source>
        <translation>&apos;%1&apos; non è un tipo supportato: usane uno tra %2.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Valore iniziale</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Commento</translation>
    </message>
    <message>
        <source>IEC 61131-3 identifier, unique ignoring case. Renaming updates every condition.</source>
        <translation>Identificatore IEC 61131-3, univoco senza distinzione tra maiuscole e minuscole. Rinominarlo aggiorna ogni condizione.</translation>
    </message>
    <message>
        <source>Elementary IEC 61131-3 type</source>
        <translation>Tipo elementare IEC 61131-3</translation>
    </message>
    <message>
        <source>Initial value, a literal of the type; empty for the type&apos;s implicit default</source>
        <translation>Valore iniziale, un letterale del tipo; vuoto per il valore predefinito implicito del tipo</translation>
    </message>
    <message>
        <source>Free text, written into the generated declarations</source>
        <translation>Testo libero, scritto nelle dichiarazioni generate</translation>
    </message>
    <message>
        <source>Line %1: the name is empty.</source>
        <translation>Riga %1: il nome è vuoto.</translation>
    </message>
    <message>
        <source>Line %1: &apos;%2&apos; is not a supported type: use one of %3.</source>
        <translation>Riga %1: &apos;%2&apos; non è un tipo supportato: usane uno tra %3.</translation>
    </message>
    <message>
        <source>There are no variables to paste: copy rows of name, type, default and comment, separated by tabs.</source>
        <translation>Non ci sono variabili da incollare: copia righe con nome, tipo, valore iniziale e commento, separati da tabulazioni.</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Uscita</translation>
    </message>
    <message>
        <source>Internal</source>
        <translation>Interna</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Ingresso</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a kind: use %2, %3 or %4.</source>
        <translation>&apos;%1&apos; non è una natura: usa %2, %3 o %4.</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Natura</translation>
    </message>
    <message>
        <source>Input: read from the machine. Output: written by the actions of nested GRAFCETs. Internal: a memory the program writes and reads.</source>
        <translation>Ingresso: letto dalla macchina. Uscita: scritta dalle azioni dei GRAFCET annidati. Interna: una memoria che il programma scrive e legge.</translation>
    </message>
    <message>
        <source>Line %1: &apos;%2&apos; is not a kind: use input, output or internal.</source>
        <translation>Riga %1: &apos;%2&apos; non è una natura: usa ingresso, uscita o interna.</translation>
    </message>
</context>
<context>
    <name>editor::VerificationPanel</name>
    <message>
        <source>&amp;Verify</source>
        <translation>&amp;Verifica</translation>
    </message>
    <message>
        <source>&amp;Show on Chart</source>
        <translation>&amp;Mostra nel diagramma</translation>
    </message>
    <message>
        <source>&amp;Replay in Simulator</source>
        <translation>&amp;Riproduci nel simulatore</translation>
    </message>
    <message>
        <source>Explore every input sequence of the GEMMA layer and report what cannot happen</source>
        <translation>Esplora ogni sequenza di ingressi del livello GEMMA e segnala ciò che non può accadere</translation>
    </message>
    <message>
        <source>Select the element of the finding on the chart</source>
        <translation>Seleziona l&apos;elemento del risultato nel diagramma</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Codice</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Scans</source>
        <translation>Cicli</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Messaggio</translation>
    </message>
    <message>
        <source>Scans of the counterexample, which the simulator can replay</source>
        <translation>Cicli del controesempio, che il simulatore può riprodurre</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copia</translation>
    </message>
    <message>
        <source>Verifying…</source>
        <translation>Verifica in corso…</translation>
    </message>
    <message>
        <source>Verification failed: %1.</source>
        <translation>Verifica non riuscita: %1.</translation>
    </message>
    <message>
        <source>Not verified yet.</source>
        <translation>Non ancora verificato.</translation>
    </message>
    <message>
        <source>Model changed since verification: verify again to update the findings.</source>
        <translation>Il modello è cambiato dalla verifica: verifica di nuovo per aggiornare i risultati.</translation>
    </message>
    <message>
        <source>Some properties do not hold (%1 configurations explored).</source>
        <translation>Alcune proprietà non sono soddisfatte (%1 configurazioni esplorate).</translation>
    </message>
    <message>
        <source>Every property holds; see the notes (%1 configurations explored).</source>
        <translation>Tutte le proprietà sono soddisfatte; vedi le note (%1 configurazioni esplorate).</translation>
    </message>
    <message>
        <source>Every property holds (%1 configurations explored).</source>
        <translation>Tutte le proprietà sono soddisfatte (%1 configurazioni esplorate).</translation>
    </message>
    <message>
        <source>The model changed since verification: verify again to replay</source>
        <translation>Il modello è cambiato dalla verifica: verifica di nuovo per riprodurre</translation>
    </message>
    <message>
        <source>Start the simulation and replay the scans that lead to the finding</source>
        <translation>Avvia la simulazione e riproduci i cicli che portano al risultato</translation>
    </message>
    <message>
        <source>Complete settings changed since verification: verify again to update the findings.</source>
        <translation>Le impostazioni di Complete sono cambiate dalla verifica: verifica di nuovo per aggiornare i risultati.</translation>
    </message>
    <message>
        <source>All Complete outputs free</source>
        <translation>Tutte le uscite Complete libere</translation>
    </message>
    <message>
        <source>Assumed Complete automatic: %1</source>
        <translation>Complete assunto automatico: %1</translation>
    </message>
    <message>
        <source>Free: the nested behaviour may complete at any scan, or never. Automatic: Complete is TRUE at every scan, as the skeleton function block. Verify assumes automatic the nested steps whose Complete is Automatic in the Simulation dock while the simulation runs; all others are free.</source>
        <translation>Libero: il comportamento interno può completarsi a qualsiasi ciclo, o mai. Automatico: Complete è TRUE a ogni ciclo, come nel blocco funzione scheletro. La verifica assume automatiche le tappe con comportamento interno il cui Complete è Automatico nel pannello Simulazione durante la simulazione; tutte le altre sono libere.</translation>
    </message>
    <message>
        <source>%1: T%2</source>
        <translation>%1: T%2</translation>
    </message>
    <message>
        <source>%1: step %2</source>
        <extracomment>A step of a nested GRAFCET: %1 the GEMMA step, %2 its number</extracomment>
        <translation>%1: tappa %2</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modello</translation>
    </message>
    <message>
        <source>%1: nested GRAFCET</source>
        <extracomment>The row that groups the findings about the nested GRAFCET of a GEMMA step, e.g. &quot;F1 Normal production&quot;</extracomment>
        <translation>%1: GRAFCET annidato</translation>
    </message>
    <message>
        <source>The findings about the nested GRAFCET of %1</source>
        <translation>I risultati sul GRAFCET annidato di %1</translation>
    </message>
    <message>
        <source>Some properties do not hold (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Alcune proprietà non sono soddisfatte (%1 configurazioni del livello GEMMA e %2 stati del programma dei due livelli esplorati).</translation>
    </message>
    <message>
        <source>Every property holds; see the notes (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Tutte le proprietà sono soddisfatte; vedi le note (%1 configurazioni del livello GEMMA e %2 stati del programma dei due livelli esplorati).</translation>
    </message>
    <message>
        <source>Every property holds (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Tutte le proprietà sono soddisfatte (%1 configurazioni del livello GEMMA e %2 stati del programma dei due livelli esplorati).</translation>
    </message>
    <message>
        <source>The exploration of both layers abstracted:</source>
        <translation>L&apos;esplorazione dei due livelli ha astratto:</translation>
    </message>
    <message>
        <source>Exact time switched on since verification: verify again to update the findings.</source>
        <translation>Tempo esatto attivato dalla verifica: verifica di nuovo per aggiornare i risultati.</translation>
    </message>
    <message>
        <source>Exact time switched off since verification: verify again to update the findings.</source>
        <translation>Tempo esatto disattivato dalla verifica: verifica di nuovo per aggiornare i risultati.</translation>
    </message>
    <message>
        <source>Exact time</source>
        <translation>Tempo esatto</translation>
    </message>
    <message>
        <source>Exact time: every timer elapses exactly when the PLC&apos;s would, counted in scans (Simulation &gt; Verify with Exact Time).</source>
        <translation>Tempo esatto: ogni temporizzatore scade esattamente quando scadrebbe quello del PLC, contato in cicli (Simulazione &gt; Verifica con tempo esatto).</translation>
    </message>
    <message>
        <source>Nothing is violated, but some properties are undecided: see the findings (%1 configurations explored).</source>
        <translation>Nulla è violato, ma alcune proprietà sono indecise: vedi i risultati (%1 configurazioni esplorate).</translation>
    </message>
    <message>
        <source>Nothing is violated, but some properties are undecided: see the findings (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Nulla è violato, ma alcune proprietà sono indecise: vedi i risultati (%1 configurazioni del livello GEMMA e %2 stati del programma dei due livelli esplorati).</translation>
    </message>
    <message>
        <source>&amp;Time limit:</source>
        <translation>&amp;Limite di tempo:</translation>
    </message>
    <message>
        <source> s</source>
        <extracomment>The unit after the verification&apos;s time limit: &quot;4 s&quot;</extracomment>
        <translation> s</translation>
    </message>
    <message>
        <source>How long a verification may run. Past it, what is not decided yet is reported as undecided (GV100) with how far the exploration got: give more time and verify again.</source>
        <translation>Quanto può durare una verifica. Oltre questo tempo, ciò che non è ancora deciso viene segnalato come indeciso (GV100), con il punto raggiunto dall&apos;esplorazione: concedete più tempo e verificate di nuovo.</translation>
    </message>
    <message>
        <source>The machine is used since verification: verify again to update the findings.</source>
        <translation>La macchina è usata dalla verifica: verifica di nuovo per aggiornare i risultati.</translation>
    </message>
    <message>
        <source>The machine is no longer used since verification: verify again to update the findings.</source>
        <translation>La macchina non è più usata dalla verifica: verifica di nuovo per aggiornare i risultati.</translation>
    </message>
    <message>
        <source>With the machine</source>
        <translation>Con la macchina</translation>
    </message>
    <message>
        <source>With the machine: the sensors the model&apos;s machine drives follow it, scan by scan, instead of taking any value (Simulation &gt; Verify with the Machine).</source>
        <translation>Con la macchina: i sensori che la macchina del modello pilota la seguono, ciclo dopo ciclo, invece di prendere qualsiasi valore (Simulazione &gt; Verifica con la macchina).</translation>
    </message>
    <message>
        <source>Single faults switched on since verification: verify again to update the findings.</source>
        <translation>Guasti singoli attivati dopo la verifica: verificare di nuovo per aggiornare i risultati.</translation>
    </message>
    <message>
        <source>Single faults switched off since verification: verify again to update the findings.</source>
        <translation>Guasti singoli disattivati dopo la verifica: verificare di nuovo per aggiornare i risultati.</translation>
    </message>
    <message>
        <source>Single faults</source>
        <translation>Guasti singoli</translation>
    </message>
    <message>
        <source>Single faults: any one sensor stuck or flickering, or one cylinder or conveyor jammed, from any scan on (Simulation &gt; Verify with Single Faults).</source>
        <translation>Guasti singoli: un sensore qualsiasi bloccato o intermittente, o un cilindro o un nastro inceppato, a partire da qualunque ciclo (Simulazione &gt; Verifica con guasti singoli).</translation>
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
        <translation>Lo zoom della scheda in primo piano. Ctrl+rotellina o un pizzico ingrandisce attorno al puntatore; Ctrl+0 adatta il disegno alla finestra, Ctrl+1 lo mostra a grandezza reale</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Editor for the GEMMA-GRAFCET method of specifying machine operating modes</source>
        <translation>Editor per il metodo GEMMA-GRAFCET, per specificare i modi di marcia e di arresto delle macchine</translation>
    </message>
    <message>
        <source>The model file to open (GG Studio JSON, GG-Generator JSON or GG Studio PLCopen XML).</source>
        <translation>Il file del modello da aprire (JSON GG Studio, JSON GG-Generator o PLCopen XML GG Studio).</translation>
    </message>
</context>
<context>
    <name>modbus::ModbusLink</name>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation>impossibile ascoltare su %1:%2: %3</translation>
    </message>
    <message>
        <source>cannot connect to %1:%2: %3</source>
        <translation>impossibile connettersi a %1:%2: %3</translation>
    </message>
    <message>
        <source>write of %1 %2..%3 to %4:%5</source>
        <translation>scrittura di %1 %2..%3 su %4:%5</translation>
    </message>
    <message>
        <source>read of %1 %2..%3 from %4:%5</source>
        <translation>lettura di %1 %2..%3 da %4:%5</translation>
    </message>
</context>
</TS>
