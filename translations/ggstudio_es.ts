<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>AddGrafcetActionCommand</name>
    <message>
        <source>Add action %1 to %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Añadir la acción %1 a la etapa %3 de %2</translation>
    </message>
</context>
<context>
    <name>AddMachineComponentCommand</name>
    <message>
        <source>Add %1 %2</source>
        <extracomment>%1: a kind of machine component (&quot;Conveyor&quot;); %2: its name</extracomment>
        <translation>Añadir %1 %2</translation>
    </message>
</context>
<context>
    <name>AddModeCommand</name>
    <message>
        <source>Add mode %1 %2</source>
        <translation>Añadir el modo %1 %2</translation>
    </message>
</context>
<context>
    <name>AddPropertyCommand</name>
    <message>
        <source>Add property</source>
        <translation>Añadir propiedad</translation>
    </message>
</context>
<context>
    <name>AddVariableCommand</name>
    <message>
        <source>Add variable %1</source>
        <translation>Añadir la variable %1</translation>
    </message>
</context>
<context>
    <name>ChartExport</name>
    <message>
        <source>GEMMA-GRAFCET chart drawn by GG Studio</source>
        <translation>Diagrama GEMMA-GRAFCET dibujado con GG Studio</translation>
    </message>
</context>
<context>
    <name>ConditionErrorText</name>
    <message>
        <source>comments are not allowed in a condition</source>
        <translation>los comentarios no están permitidos en una condición</translation>
    </message>
    <message>
        <source>use = to compare; := is assignment</source>
        <translation>use = para comparar; := es la asignación</translation>
    </message>
    <message>
        <source>use = to compare; == is not Structured Text</source>
        <translation>use = para comparar; == no es Structured Text</translation>
    </message>
    <message>
        <source>use &lt;&gt; for &apos;not equal&apos;</source>
        <translation>use &lt;&gt; para &apos;distinto de&apos;</translation>
    </message>
    <message>
        <source>use NOT for negation</source>
        <translation>use NOT para la negación</translation>
    </message>
    <message>
        <source>use AND (or &amp;) for &apos;and&apos;</source>
        <translation>use AND (o &amp;) para &apos;y&apos;</translation>
    </message>
    <message>
        <source>use OR for &apos;or&apos;</source>
        <translation>use OR para &apos;o&apos;</translation>
    </message>
    <message>
        <source>&apos;**&apos; (power) is not supported in a condition</source>
        <translation>&apos;**&apos; (potencia) no está admitido en una condición</translation>
    </message>
    <message>
        <source>&apos;;&apos; is not allowed in a condition: write only the expression</source>
        <translation>&apos;;&apos; no está permitido en una condición: escriba solo la expresión</translation>
    </message>
    <message>
        <source>the text contains bytes that are not valid UTF-8</source>
        <translation>el texto contiene bytes que no son UTF-8 válido</translation>
    </message>
    <message>
        <source>&apos;%1&apos; contains a non-ASCII character: names use ASCII letters, digits and _ only</source>
        <translation>&apos;%1&apos; contiene un carácter no ASCII: los nombres solo usan letras ASCII, dígitos y _</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not supported: write plain decimal numbers, TRUE or FALSE (no typed, based or time literals)</source>
        <translation>&apos;%1&apos; no está admitido: escriba números decimales simples, TRUE o FALSE (sin literales con tipo, en base o de tiempo)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: qualified names are not allowed, write the variable name alone</source>
        <translation>&apos;%1&apos;: los nombres calificados no están permitidos, escriba solo el nombre de la variable</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid number</source>
        <translation>&apos;%1&apos; no es un número válido</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: write only the boolean expression, without IF ... THEN</source>
        <extracomment>%1: IF, THEN, ELSE... as written</extracomment>
        <translation>&apos;%1&apos; no está permitido en una condición: escriba solo la expresión booleana, sin IF ... THEN</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: it is a type name</source>
        <translation>&apos;%1&apos; no está permitido en una condición: es un nombre de tipo</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: it is an IEC 61131-3 keyword</source>
        <translation>&apos;%1&apos; no está permitido en una condición: es una palabra clave IEC 61131-3</translation>
    </message>
    <message>
        <source>unexpected control character (byte %1)</source>
        <extracomment>%1: the byte in hexadecimal (0x1B)</extracomment>
        <translation>carácter de control inesperado (byte %1)</translation>
    </message>
    <message>
        <source>unexpected character &apos;%1&apos;</source>
        <translation>carácter &apos;%1&apos; inesperado</translation>
    </message>
    <message>
        <source>condition too complex: operators nested more than %1 levels deep</source>
        <translation>condición demasiado compleja: operadores anidados en más de %1 niveles</translation>
    </message>
    <message>
        <source>condition nested too deeply: more than %1 levels of parentheses</source>
        <translation>condición demasiado anidada: más de %1 niveles de paréntesis</translation>
    </message>
    <message>
        <source>condition nested too deeply: more than %1 levels of unary operators</source>
        <translation>condición demasiado anidada: más de %1 niveles de operadores unarios</translation>
    </message>
    <message>
        <source>unmatched &apos;)&apos;: no &apos;(&apos; opens it</source>
        <translation>&apos;)&apos; sin pareja: ningún &apos;(&apos; lo abre</translation>
    </message>
    <message>
        <source>expected an operand before &apos;%1&apos;</source>
        <extracomment>%1: an operator the condition starts with</extracomment>
        <translation>se esperaba un operando antes de &apos;%1&apos;</translation>
    </message>
    <message>
        <source>empty parentheses: expected an expression inside &apos;( )&apos;</source>
        <translation>paréntesis vacíos: se esperaba una expresión dentro de &apos;( )&apos;</translation>
    </message>
    <message>
        <source>expected an operand after &apos;%1&apos;</source>
        <extracomment>%1: the operator or &apos;(&apos; the condition ends with</extracomment>
        <translation>se esperaba un operando después de &apos;%1&apos;</translation>
    </message>
    <message>
        <source>expected an operand after &apos;%1&apos;, found &apos;%2&apos;</source>
        <extracomment>%1: an operator or &apos;(&apos;; %2: what follows it instead of an operand</extracomment>
        <translation>se esperaba un operando después de &apos;%1&apos;, se encontró &apos;%2&apos;</translation>
    </message>
    <message>
        <source>unmatched &apos;(&apos; at column %1: missing &apos;)&apos;</source>
        <extracomment>%1: a column number</extracomment>
        <translation>&apos;(&apos; sin pareja en la columna %1: falta &apos;)&apos;</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos;: expected an operator or &apos;)&apos; to close the &apos;(&apos; at column %2</source>
        <extracomment>%1: what was found; %2: the column of the &apos;(&apos;</extracomment>
        <translation>&apos;%1&apos; inesperado: se esperaba un operador o &apos;)&apos; para cerrar el &apos;(&apos; de la columna %2</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete condition</source>
        <translation>&apos;%1&apos; inesperado después de una condición completa</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete condition (missing operator?)</source>
        <translation>&apos;%1&apos; inesperado después de una condición completa (¿falta un operador?)</translation>
    </message>
    <message>
        <source>an edge (RE, FE, ↑, ↓) applies to a variable name</source>
        <translation>un flanco (RE, FE, ↑, ↓) se aplica a un nombre de variable</translation>
    </message>
    <message>
        <source>an edge (RE, FE, ↑, ↓) applies to a variable name, not to &apos;%1&apos;</source>
        <extracomment>%1: what follows RE, FE, ↑ or ↓ instead of a variable name</extracomment>
        <translation>un flanco (RE, FE, ↑, ↓) se aplica a un nombre de variable, no a «%1»</translation>
    </message>
    <message>
        <source>the duration &apos;%1&apos; must be followed by /X&lt;step&gt;, as in %1/X3</source>
        <extracomment>%1: a duration such as 5s; X3 is step 3&apos;s activity, keep it as is</extracomment>
        <translation>la duración «%1» debe ir seguida de /X&lt;etapa&gt;, como en %1/X3</translation>
    </message>
    <message>
        <source>expected a step activity X&lt;step&gt; after &apos;/&apos; of the duration</source>
        <translation>se esperaba una actividad de etapa X&lt;etapa&gt; tras la «/» de la duración</translation>
    </message>
    <message>
        <source>expected a step activity X&lt;step&gt; after &apos;/&apos; of the duration, found &apos;%1&apos;</source>
        <translation>se esperaba una actividad de etapa X&lt;etapa&gt; tras la «/» de la duración, se encontró «%1»</translation>
    </message>
    <message>
        <source>the duration &apos;%1&apos; is zero: write a positive duration</source>
        <translation>la duración «%1» es cero: escriba una duración positiva</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid duration: write for example 200ms, 5s, 1m30s or T#5s (units d, h, m, s, ms, largest first)</source>
        <translation>«%1» no es una duración válida: escriba por ejemplo 200ms, 5s, 1m30s o T#5s (unidades d, h, m, s, ms, de mayor a menor)</translation>
    </message>
    <message>
        <source>empty action: write for example Valve, S Valve, R Valve or Count := Count + 1</source>
        <translation>acción vacía: escriba por ejemplo Valve, S Valve, R Valve o Count := Count + 1</translation>
    </message>
    <message>
        <source>an action writes a variable: &apos;%1&apos; is not a variable name</source>
        <translation>una acción escribe una variable: «%1» no es un nombre de variable</translation>
    </message>
    <message>
        <source>the qualifier &apos;%1&apos; is not supported: use N (or none), S, R or an assignment V := value</source>
        <translation>el calificador «%1» no está soportado: use N (o ninguno), S, R o una asignación V := valor</translation>
    </message>
    <message>
        <source>an assignment takes no qualifier: write V := value, without &apos;%1&apos;</source>
        <translation>una asignación no lleva calificador: escriba V := valor, sin «%1»</translation>
    </message>
    <message>
        <source>a stored action (%1) takes no IF condition: only continuous actions are conditional</source>
        <extracomment>%1: the qualifier S or R</extracomment>
        <translation>una acción memorizada (%1) no lleva condición IF: solo las acciones continuas son condicionales</translation>
    </message>
    <message>
        <source>expected a value after &apos;:=&apos;</source>
        <translation>se esperaba un valor tras «:=»</translation>
    </message>
    <message>
        <source>expected a condition after IF</source>
        <translation>se esperaba una condición tras IF</translation>
    </message>
    <message>
        <source>use := to assign a value; = compares</source>
        <translation>use := para asignar un valor; = compara</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete action</source>
        <translation>«%1» inesperado tras una acción completa</translation>
    </message>
    <message>
        <source>empty condition: write when the transition fires (TRUE if it is always ready), or hide the transition if the machine does not need it</source>
        <translation>condición vacía: escriba cuándo se franquea la transición (TRUE si siempre está lista), u oculte la transición si la máquina no la necesita</translation>
    </message>
    <message>
        <source>a property starts with never or always</source>
        <translation>una propiedad empieza por never o always</translation>
    </message>
    <message>
        <source>a property starts with never or always, not &apos;%1&apos;</source>
        <translation>una propiedad empieza por never o always, no por &apos;%1&apos;</translation>
    </message>
    <message>
        <source>expected a GEMMA step after &apos;in&apos;</source>
        <translation>se esperaba una etapa GEMMA después de &apos;in&apos;</translation>
    </message>
    <message>
        <source>expected a GEMMA step after &apos;in&apos;, found &apos;%1&apos;</source>
        <translation>se esperaba una etapa GEMMA después de &apos;in&apos;, se encontró &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>ConditionTypeErrorText</name>
    <message>
        <source>&apos;%1&apos; is an integer</source>
        <extracomment>%1: a subexpression of the condition</extracomment>
        <translation>&apos;%1&apos; es un entero</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a real number</source>
        <translation>&apos;%1&apos; es un número real</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is of unknown type</source>
        <translation>&apos;%1&apos; es de tipo desconocido</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is %2</source>
        <extracomment>%1: a subexpression of the condition; %2: its IEC type (INT, BOOL)</extracomment>
        <translation>&apos;%1&apos; es de tipo %2</translation>
    </message>
    <message>
        <source>a condition must be BOOL, but %1</source>
        <extracomment>%1: the condition and what it is (&quot;&apos;Speed + 1&apos; is an integer&quot;)</extracomment>
        <translation>una condición debe ser BOOL, pero %1</translation>
    </message>
    <message>
        <source>%1 needs a BOOL operand, but %2</source>
        <extracomment>%1: NOT; %2: its operand and what it is (&quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 necesita un operando BOOL, pero %2</translation>
    </message>
    <message>
        <source>unary %1 needs a numeric operand, but %2</source>
        <extracomment>%1: &apos;-&apos; (negation); %2: its operand and what it is (&quot;&apos;Start&apos; is BOOL&quot;)</extracomment>
        <translation>el %1 unario necesita un operando numérico, pero %2</translation>
    </message>
    <message>
        <source>%1 needs BOOL operands, but %2</source>
        <extracomment>%1: AND, OR or XOR; %2: the operand at fault and what it is (&quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 necesita operandos BOOL, pero %2</translation>
    </message>
    <message>
        <source>%1 needs numeric operands, but %2</source>
        <extracomment>%1: a comparison or arithmetic operator (&apos;&lt;&apos;, &apos;+&apos;); %2: the operand at fault and what it is</extracomment>
        <translation>%1 necesita operandos numéricos, pero %2</translation>
    </message>
    <message>
        <source>%1 needs integer operands, but %2</source>
        <extracomment>%1: MOD; %2: the operand at fault and what it is (&quot;&apos;Temp&apos; is REAL&quot;)</extracomment>
        <translation>%1 necesita operandos enteros, pero %2</translation>
    </message>
    <message>
        <source>%1 needs two operands of the same kind, but %2 and %3</source>
        <extracomment>%1: &apos;=&apos; or &apos;&lt;&gt;&apos;; %2, %3: each operand and what it is (&quot;&apos;Start&apos; is BOOL&quot;, &quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 necesita dos operandos de la misma clase, pero %2 y %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range: integer literals go up to 9223372036854775807 (LINT)</source>
        <translation>&apos;%1&apos; está fuera de rango: los literales enteros llegan hasta 9223372036854775807 (LINT)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range for LREAL (-1.8E308..1.8E308)</source>
        <translation>&apos;%1&apos; está fuera del rango de LREAL (-1.8E308..1.8E308)</translation>
    </message>
</context>
<context>
    <name>ConveyorItem</name>
    <message>
        <source>Parts out: %1</source>
        <translation>Piezas salidas: %1</translation>
    </message>
</context>
<context>
    <name>DeclarationFixText</name>
    <message>
        <source>Declare &apos;%1&apos; as OUTPUT %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Declarar &apos;%1&apos; como salida %2</translation>
    </message>
    <message>
        <source>Declare &apos;%1&apos; as INTERNAL %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Declarar &apos;%1&apos; como variable interna %2</translation>
    </message>
    <message>
        <source>Declare &apos;%1&apos; as INPUT %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Declarar &apos;%1&apos; como entrada %2</translation>
    </message>
</context>
<context>
    <name>DiagnosticText</name>
    <message>
        <source>the name is empty</source>
        <translation>el nombre está vacío</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid IEC 61131-3 identifier: use ASCII letters, digits and &apos;_&apos;, not starting with a digit</source>
        <translation>&apos;%1&apos; no es un identificador IEC 61131-3 válido: use letras ASCII, dígitos y &apos;_&apos;, sin empezar por un dígito</translation>
    </message>
    <message>
        <source>&apos;%1&apos; contains &apos;__&apos;, which IEC 61131-3 identifiers may not</source>
        <translation>&apos;%1&apos; contiene &apos;__&apos;, lo que no admiten los identificadores IEC 61131-3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; ends with &apos;_&apos;, which IEC 61131-3 identifiers may not</source>
        <translation>&apos;%1&apos; termina en &apos;_&apos;, lo que no admiten los identificadores IEC 61131-3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is an IEC 61131-3 keyword or type name</source>
        <translation>&apos;%1&apos; es una palabra clave o un nombre de tipo IEC 61131-3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a name the generated code uses</source>
        <translation>&apos;%1&apos; es un nombre que usa el código generado</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; does not occur in the condition.</source>
        <translation>La memoria de &apos;%2&apos; en %1 no es válida: &apos;%2&apos; no aparece en la condición.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is ambiguous: the condition uses both %2 and NOT %2, so the token could be neither normally open nor normally closed.</source>
        <translation>La memoria de &apos;%2&apos; en %1 es ambigua: la condición usa a la vez %2 y NOT %2, por lo que la memoria no puede ser ni normalmente abierta ni normalmente cerrada.</translation>
    </message>
    <message>
        <source>The token in %1 names &apos;%2&apos;, which is not a declared variable.</source>
        <translation>Una memoria de %1 se refiere a &apos;%2&apos;, que no es una variable declarada.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; is compared with &apos;=&apos; or &apos;&lt;&gt;&apos; in the condition, where it has no polarity; a token can only replace a literal %2 or NOT %2.</source>
        <translation>La memoria de &apos;%2&apos; en %1 no es válida: &apos;%2&apos; se compara con &apos;=&apos; o &apos;&lt;&gt;&apos; en la condición, donde no tiene polaridad; una memoria solo puede sustituir a un literal %2 o NOT %2.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 has no effect and is not generated: family transitions never wait for Complete.</source>
        <translation>La memoria de &apos;%2&apos; en %1 no tiene efecto y no se genera: las transiciones de familia nunca esperan a Complete.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 has no effect and is not generated: its source %3 is a simple step.</source>
        <translation>La memoria de &apos;%2&apos; en %1 no tiene efecto y no se genera: su etapa de origen %3 es una etapa simple.</translation>
    </message>
    <message>
        <source>The initial step %1 is hidden: the PLC would start in a state that has no code.</source>
        <translation>La etapa inicial %1 está oculta: el PLC arrancaría en un estado sin código.</translation>
    </message>
    <message>
        <source>Step %1 has no visible outgoing transition: the machine would stay in it forever.</source>
        <translation>La etapa %1 no tiene ninguna transición de salida visible: la máquina se quedaría en ella para siempre.</translation>
    </message>
    <message>
        <source>Step %1 has no visible incoming transition: it can never become active.</source>
        <translation>La etapa %1 no tiene ninguna transición de entrada visible: nunca puede activarse.</translation>
    </message>
    <message>
        <source>The family transition %1 is negated, which has no effect: family transitions never wait for Complete.</source>
        <translation>La transición de familia %1 está negada, lo que no tiene efecto: las transiciones de familia nunca esperan a Complete.</translation>
    </message>
    <message>
        <source>The condition of %1 is FALSE: the transition can never fire (hide it instead).</source>
        <translation>La condición de %1 es FALSE: la transición nunca puede franquearse (ocúltela en su lugar).</translation>
    </message>
    <message>
        <source>Step %1 cannot be reached from the initial step %2 through visible transitions: it can never become active.</source>
        <translation>La etapa %1 no es alcanzable desde la etapa inicial %2 a través de transiciones visibles: nunca puede activarse.</translation>
    </message>
    <message>
        <source>Transition %1 is negated, which has no effect: its source %2 is a simple step, and negation only changes transitions out of macro and enclosing steps.</source>
        <translation>La transición %1 está negada, lo que no tiene efecto: su etapa de origen %2 es una etapa simple, y la negación solo cambia las transiciones que salen de macroetapas y etapas encapsulantes.</translation>
    </message>
    <message>
        <source>The condition of %1 is TRUE and does not wait for Complete: the lower-priority transitions %2 can never fire.</source>
        <translation>La condición de %1 es TRUE y no espera a Complete: las transiciones de menor prioridad %2 nunca pueden franquearse.</translation>
    </message>
    <message>
        <source>Invalid variable name: %1.</source>
        <translation>Nombre de variable no válido: %1.</translation>
    </message>
    <message>
        <source>Syntax error in the condition of %1: %2.</source>
        <translation>Error de sintaxis en la condición de %1: %2.</translation>
    </message>
    <message>
        <source>In the condition of %1: &apos;%2&apos; is not a declared variable.</source>
        <translation>En la condición de %1: &apos;%2&apos; no es una variable declarada.</translation>
    </message>
    <message>
        <source>Type error in the condition of %1: %2.</source>
        <translation>Error de tipo en la condición de %1: %2.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; is %3, and only BOOL variables can have a token.</source>
        <translation>La memoria de &apos;%2&apos; en %1 no es válida: &apos;%2&apos; es de tipo %3, y solo las variables BOOL pueden tener memoria.</translation>
    </message>
    <message>
        <source>The default value of variable &apos;%1&apos; is invalid: %2.</source>
        <translation>El valor inicial de la variable &apos;%1&apos; no es válido: %2.</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Advertencia</translation>
    </message>
    <message>
        <source>Information</source>
        <translation>Información</translation>
    </message>
    <message>
        <source>The verification reached its time or size limit before every property was decided: the properties not reported were not decided.</source>
        <translation>La verificación alcanzó su límite de tiempo o de tamaño antes de decidir todas las propiedades: las propiedades no indicadas no se decidieron.</translation>
    </message>
    <message>
        <source>The verification reached its time or size limit before deciding everything about %1: what is not reported about it was not decided. Every other finding holds.</source>
        <translation>La verificación alcanzó su límite de tiempo o de tamaño antes de decidirlo todo sobre %1: lo que no se indica sobre ello no se decidió. Todos los demás resultados son válidos.</translation>
    </message>
    <message>
        <source>Step %1 can never become active: no effective transition leads to it.</source>
        <translation>La etapa %1 nunca puede activarse: ninguna transición efectiva lleva a ella.</translation>
    </message>
    <message>
        <source>Step %1 can never become active: no situation reachable from the initial step lets %2 fire.</source>
        <translation>La etapa %1 nunca puede activarse: ninguna situación alcanzable desde la etapa inicial permite franquear %2.</translation>
    </message>
    <message>
        <source>Transition %1 can never fire: its condition is never TRUE in a situation reachable from the initial step.</source>
        <translation>La transición %1 nunca puede franquearse: su condición no es TRUE en ninguna situación alcanzable desde la etapa inicial.</translation>
    </message>
    <message>
        <source>Transition %1 can never fire: whenever its condition holds, a transition of higher priority fires first (%2).</source>
        <translation>La transición %1 nunca puede franquearse: siempre que su condición se cumple, una transición de mayor prioridad se franquea antes (%2).</translation>
    </message>
    <message>
        <source>The condition of %1 is always TRUE: no own transition of an F step can ever fire.</source>
        <translation>La condición de %1 es siempre TRUE: ninguna transición propia de una etapa F puede franquearse nunca.</translation>
    </message>
    <message>
        <source>The condition of %1 is always TRUE when %3 is active: %2 can never fire.</source>
        <translation>La condición de %1 es siempre TRUE cuando %3 está activa: %2 nunca puede franquearse.</translation>
    </message>
    <message>
        <source>%1 and %2 can both be TRUE in the same scan: the priority decides, %1 fires.</source>
        <translation>%1 y %2 pueden ser TRUE en el mismo ciclo: decide la prioridad, se franquea %1.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead to a situation from which the initial step can never become active again.</source>
        <translation>Una vez activa %1, las entradas pueden llevar a una situación desde la que la etapa inicial nunca puede volver a activarse.</translation>
    </message>
    <message>
        <source>Step %1 can get stuck: the inputs can lead to a situation in it from which no transition out of it can ever fire.</source>
        <translation>La etapa %1 puede quedarse bloqueada: las entradas pueden llevar a una situación en ella en la que ninguna de sus transiciones de salida puede franquearse nunca.</translation>
    </message>
    <message>
        <source>The emergency stop D1 can never be entered from %1: the family transition F-&gt;D1 is not effective and %1 has no transition to D1.</source>
        <translation>La parada de emergencia D1 nunca puede alcanzarse desde %1: la transición de familia F-&gt;D1 no es efectiva y %1 no tiene ninguna transición hacia D1.</translation>
    </message>
    <message>
        <source>In some situations of %1 the emergency stop D1 cannot be entered in one scan, whatever the inputs: %2 cannot fire there.</source>
        <translation>En algunas situaciones de %1 la parada de emergencia D1 no puede alcanzarse en un ciclo, sean cuales sean las entradas: %2 no puede franquearse allí.</translation>
    </message>
    <message>
        <source>Not confirmed: a condition uses a comparison the verifier cannot decide, and the counterexample does not replay.</source>
        <translation>No confirmado: una condición usa una comparación que el verificador no puede decidir, y el contraejemplo no se reproduce.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 has no initial step: it would never do anything.</source>
        <translation>El GRAFCET anidado de %1 no tiene etapa inicial: nunca haría nada.</translation>
    </message>
    <message>
        <source>Step %2 of %1 cannot be reached from the initial steps through transitions: it can never become active.</source>
        <translation>La etapa %2 de %1 no se puede alcanzar desde las etapas iniciales mediante transiciones: nunca puede activarse.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 never sets Complete, so %2, which wait for it, can never fire.</source>
        <extracomment>%2: the GEMMA transitions that wait for Complete</extracomment>
        <translation>El GRAFCET anidado de %1 nunca activa Complete, así que %2, que lo esperan, nunca pueden dispararse.</translation>
    </message>
    <message>
        <source>The selection after step %2 of %1 is not exclusive: %3 and %4 can both fire (with %5), and both branches then start.</source>
        <extracomment>%3, %4: two nested transitions; %5: the values that make both receptivities TRUE</extracomment>
        <translation>La selección tras la etapa %2 de %1 no es exclusiva: %3 y %4 pueden dispararse a la vez (con %5), y entonces arrancan ambas ramas.</translation>
    </message>
    <message>
        <source>Step %2 of %1 has no outgoing transition and does not set Complete: the GRAFCET stops there for good.</source>
        <translation>La etapa %2 de %1 no tiene transición de salida y no activa Complete: el GRAFCET se detiene ahí para siempre.</translation>
    </message>
    <message>
        <source>Under the until-stable rule, step %2 of %1 is left in the call that enters it (%3 is always TRUE): the GEMMA layer never sees what it does to Complete.</source>
        <translation>Con la regla «hasta estabilidad», la etapa %2 de %1 se abandona en la misma llamada que la activa (%3 siempre es verdadera): la capa GEMMA nunca ve lo que hace con Complete.</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has a name the code of the nested GRAFCETs uses: %2.</source>
        <extracomment>%2: why, in English (a technical reason)</extracomment>
        <translation>La variable «%1» tiene un nombre que usa el código de los GRAFCET anidados: %2.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 is kept but not used: %1 is hidden.</source>
        <translation>El GRAFCET anidado de %1 se conserva pero no se usa: %1 está oculta.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 is kept but not used: %1 is a simple step.</source>
        <translation>El GRAFCET anidado de %1 se conserva pero no se usa: %1 es una etapa simple.</translation>
    </message>
    <message>
        <source>The condition of %1 is empty: write when it fires (TRUE if it is always ready), or hide the transition if your machine does not need it.</source>
        <translation>La condición de %1 está vacía: escriba cuándo se franquea (TRUE si siempre está lista), u oculte la transición si su máquina no la necesita.</translation>
    </message>
    <message>
        <source>Step %2 of the nested GRAFCET of %1 can never become active.</source>
        <extracomment>%1: a GEMMA step; %2: the number of a step of its nested GRAFCET</extracomment>
        <translation>La etapa %2 del GRAFCET anidado de %1 nunca puede activarse.</translation>
    </message>
    <message>
        <source>Transition T%2 of the nested GRAFCET of %1 can never fire.</source>
        <extracomment>%1: a GEMMA step; %2: the number of a transition of its nested GRAFCET</extracomment>
        <translation>La transición T%2 del GRAFCET anidado de %1 nunca puede franquearse.</translation>
    </message>
    <message>
        <source>Step %2 of the nested GRAFCET of %1 can be activated while it is already active: the GRAFCET is not safe.</source>
        <translation>La etapa %2 del GRAFCET anidado de %1 puede activarse cuando ya está activa: el GRAFCET no es seguro.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 can be Unstable: its evolutions do not settle within one scan.</source>
        <translation>El GRAFCET anidado de %1 puede quedar inestable (Unstable): sus evoluciones no se estabilizan en un ciclo.</translation>
    </message>
    <message>
        <source>Transitions T%3 and T%4 of the nested GRAFCET of %1 can fire together from step %2: both branches of the selection start.</source>
        <extracomment>%2: a nested step; %3, %4: the numbers of two nested transitions</extracomment>
        <translation>Las transiciones T%3 y T%4 del GRAFCET anidado de %1 pueden franquearse a la vez desde la etapa %2: arrancan las dos ramas de la selección.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead its nested GRAFCET to a situation from which Complete never becomes TRUE.</source>
        <translation>Una vez activa %1, las entradas pueden llevar su GRAFCET anidado a una situación desde la que Complete nunca llega a TRUE.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead its nested GRAFCET to a situation from which Complete never becomes TRUE: %2 can no longer fire.</source>
        <extracomment>%2: the GEMMA transitions that wait for Complete</extracomment>
        <translation>Una vez activa %1, las entradas pueden llevar su GRAFCET anidado a una situación desde la que Complete nunca llega a TRUE: %2 ya no puede franquearse.</translation>
    </message>
    <message>
        <source>%1 waits for the Complete of %2, which never becomes TRUE: it can never fire.</source>
        <translation>%1 espera el Complete de %2, que nunca llega a TRUE: nunca puede franquearse.</translation>
    </message>
    <message>
        <source>Steps %2 and %3 of the nested GRAFCET of %1 can write different values to &apos;%4&apos; in the same scan: the result depends on the order of the actions.</source>
        <translation>Las etapas %2 y %3 del GRAFCET anidado de %1 pueden escribir valores distintos en &apos;%4&apos; en el mismo ciclo: el resultado depende del orden de las acciones.</translation>
    </message>
    <message>
        <source>The continuous output &apos;%2&apos; can still be TRUE in the scan in which the emergency stop %1 is entered.</source>
        <translation>La salida continua &apos;%2&apos; aún puede ser TRUE en el ciclo en que se entra en la parada de emergencia %1.</translation>
    </message>
    <message>
        <source>The stored output &apos;%2&apos; can still be TRUE in the scan in which the emergency stop %1 is entered: stored actions are memories, only continuous outputs drop with the state.</source>
        <translation>La salida memorizada &apos;%2&apos; aún puede ser TRUE en el ciclo en que se entra en la parada de emergencia %1: las acciones memorizadas son memorias, solo las salidas continuas caen con el estado.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; does not hold.</source>
        <translation>La propiedad &apos;%1&apos; no se cumple.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; holds in every reachable scan, with the abstractions the verification lists.</source>
        <translation>La propiedad &apos;%1&apos; se cumple en todo ciclo alcanzable, con las abstracciones que indica la verificación.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; holds in every reachable scan.</source>
        <translation>La propiedad &apos;%1&apos; se cumple en todo ciclo alcanzable.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; cannot be checked: it is empty.</source>
        <translation>La propiedad &apos;%1&apos; no se puede comprobar: está vacía.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; cannot be checked: %2.</source>
        <extracomment>%2: why, in English (the property checker&apos;s message)</extracomment>
        <translation>La propiedad &apos;%1&apos; no se puede comprobar: %2.</translation>
    </message>
    <message>
        <source>The exploration of both layers reached its time or size limit: what it found is reported, but nothing about the nested GRAFCETs or the properties is proved.</source>
        <translation>La exploración de los dos niveles alcanzó su límite de tiempo o de tamaño: se informa de lo encontrado, pero no se demuestra nada sobre los GRAFCET anidados ni sobre las propiedades.</translation>
    </message>
    <message>
        <source>Not confirmed: the run found under the abstractions of the verification does not replay in the simulator.</source>
        <translation>No confirmado: la ejecución hallada con las abstracciones de la verificación no se reproduce en el simulador.</translation>
    </message>
    <message>
        <source>Not confirmed: decided on the GEMMA layer with every Complete free, and the run does not replay with the nested GRAFCETs.</source>
        <translation>No confirmado: decidido en la capa GEMMA con cada Complete libre, y la ejecución no se reproduce con los GRAFCET anidados.</translation>
    </message>
    <message>
        <source>In the condition of %1: &apos;%2&apos; divides by zero: on the PLC an integer division or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / 0)</extracomment>
        <translation>En la condición de %1: &apos;%2&apos; divide por cero: en el PLC una división entera o un MOD por cero detiene la tarea con un fallo, y una división REAL da INF o NaN.</translation>
    </message>
    <message>
        <source>In the condition of %1: the divisor of &apos;%2&apos; can be zero: an integer division or MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / Batch)</extracomment>
        <translation>En la condición de %1: el divisor de &apos;%2&apos; puede ser cero: una división entera o un MOD por cero detiene el PLC con un fallo (y la simulación), una división REAL da INF o NaN.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; is undecided: neither proved nor shown violated (%2).</source>
        <extracomment>%2: why, in English (the verifier&apos;s reason)</extracomment>
        <translation>La propiedad &apos;%1&apos; está sin decidir: ni demostrada ni mostrada incumplida (%2).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the function block of enclosing step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variable &apos;%1&apos; tiene el nombre del bloque de funciones de la etapa encapsulante %2 en el código generado: cambie el nombre de la variable (por ejemplo a &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the function block of macro-step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variable &apos;%1&apos; tiene el nombre del bloque de funciones de la macroetapa %2 en el código generado: cambie el nombre de la variable (por ejemplo a &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the instance of enclosing step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variable &apos;%1&apos; tiene el nombre de la instancia de la etapa encapsulante %2 en el código generado: cambie el nombre de la variable (por ejemplo a &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the instance of macro-step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variable &apos;%1&apos; tiene el nombre de la instancia de la macroetapa %2 en el código generado: cambie el nombre de la variable (por ejemplo a &apos;%3&apos;).</translation>
    </message>
    <message>
        <source>Enclosing step %1 declares its function block %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La etapa encapsulante %1 declara su bloque de funciones %2 en el código generado, y la variable &apos;%3&apos; tiene ese nombre: cambie el nombre de la variable (por ejemplo a &apos;%4&apos;), o convierta %1 en una etapa simple.</translation>
    </message>
    <message>
        <source>Macro-step %1 declares its function block %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La macroetapa %1 declara su bloque de funciones %2 en el código generado, y la variable &apos;%3&apos; tiene ese nombre: cambie el nombre de la variable (por ejemplo a &apos;%4&apos;), o convierta %1 en una etapa simple.</translation>
    </message>
    <message>
        <source>Enclosing step %1 declares its instance %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La etapa encapsulante %1 declara su instancia %2 en el código generado, y la variable &apos;%3&apos; tiene ese nombre: cambie el nombre de la variable (por ejemplo a &apos;%4&apos;), o convierta %1 en una etapa simple.</translation>
    </message>
    <message>
        <source>Macro-step %1 declares its instance %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La macroetapa %1 declara su instancia %2 en el código generado, y la variable &apos;%3&apos; tiene ese nombre: cambie el nombre de la variable (por ejemplo a &apos;%4&apos;), o convierta %1 en una etapa simple.</translation>
    </message>
    <message>
        <source>%2 is read in %3 and by its level in %4, which can fire right after it: while %2 stays TRUE, both fire in the same scan and step %5 of %1 is passed through; read its rising edge in %4 (↑%2) so that each press fires one transition.</source>
        <extracomment>%2: a BOOL input; %3, %4: two nested transitions; %5: the steps between them</extracomment>
        <translation>%2 se lee en %3 y por su nivel en %4, que puede dispararse justo después: mientras %2 siga en TRUE, ambas se disparan en el mismo ciclo y la etapa %5 de %1 se atraviesa; lea su flanco ascendente en %4 (↑%2) para que cada pulsación dispare una sola transición.</translation>
    </message>
    <message>
        <source>%2 is read in %3 and by its level in %4, which can fire right after it: while %2 stays TRUE, both fire in consecutive scans and step %5 of %1 is passed through; read its rising edge in %4 (↑%2) so that each press fires one transition.</source>
        <translation>%2 se lee en %3 y por su nivel en %4, que puede dispararse justo después: mientras %2 siga en TRUE, ambas se disparan en ciclos consecutivos y la etapa %5 de %1 se atraviesa; lea su flanco ascendente en %4 (↑%2) para que cada pulsación dispare una sola transición.</translation>
    </message>
    <message>
        <source>The selection after step %2 of %1 is not complete: with %4 none of %3 fires and the GRAFCET waits in step %2; add a branch for these values unless waiting is intended.</source>
        <extracomment>%3: the branches (T1, T2); %4: values of the variables (CP1 = TRUE, CP2 = FALSE)</extracomment>
        <translation>La selección tras la etapa %2 de %1 no es completa: con %4 no se dispara ninguna de %3 y el GRAFCET espera en la etapa %2; añada una rama para estos valores, salvo que la espera sea intencionada.</translation>
    </message>
    <message>
        <source>Not confirmed: its counterexample does not replay to it in the simulator.</source>
        <translation>No confirmado: su contraejemplo no lo reproduce en el simulador.</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; is used by no condition, receptivity or action that generates code.</source>
        <translation>La variable &apos;%1&apos; no la usa ninguna condición, receptividad o acción que genere código.</translation>
    </message>
    <message>
        <source>Not confirmed: the run found under the abstractions of the verification does not replay in the simulator, and the search for one with time counted in scans stopped at the time or size limit (a longer time limit may find it).</source>
        <translation>No confirmado: la ejecución hallada con las abstracciones de la verificación no se reproduce en el simulador, y la búsqueda de una con el tiempo contado en ciclos se detuvo en el límite de tiempo o de tamaño (un límite de tiempo mayor puede encontrarla).</translation>
    </message>
</context>
<context>
    <name>EditMachineComponentCommand</name>
    <message>
        <source>Edit %1</source>
        <translation>Editar %1</translation>
    </message>
</context>
<context>
    <name>ElementLabels</name>
    <message>
        <source>F (family)</source>
        <translation>F (familia)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <extracomment>a transition: source step, arrow, target step</extracomment>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Simple step</source>
        <translation>Etapa simple</translation>
    </message>
    <message>
        <source>Macro-step</source>
        <translation>Macroetapa</translation>
    </message>
    <message>
        <source>Enclosing step</source>
        <translation>Etapa encapsulante</translation>
    </message>
    <message>
        <source>hidden</source>
        <translation>oculta</translation>
    </message>
    <message>
        <source>source %1 hidden</source>
        <translation>etapa de origen %1 oculta</translation>
    </message>
    <message>
        <source>target %1 hidden</source>
        <translation>etapa de destino %1 oculta</translation>
    </message>
</context>
<context>
    <name>ExampleModels</name>
    <message>
        <source>Drilling Cell</source>
        <translation>Célula de taladrado</translation>
    </message>
    <message>
        <source>A machine that clamps, drills and marks parts: GEMMA states with four nested GRAFCETs, ready to simulate</source>
        <translation>Una máquina que sujeta, taladra y marca piezas: estados GEMMA con cuatro GRAFCET anidados, lista para simular</translation>
    </message>
    <message>
        <source>Drilling Cell with Mistakes</source>
        <translation>Célula de taladrado con errores</translation>
    </message>
    <message>
        <source>The same machine with one mistake for each check of the nested GRAFCETs, to see what the Problems panel reports</source>
        <translation>La misma máquina con un error para cada comprobación de los GRAFCET anidados, para ver lo que indica el panel Problemas</translation>
    </message>
    <message>
        <source>The example %1 is missing from this build.</source>
        <translation>El ejemplo %1 no está incluido en esta compilación.</translation>
    </message>
    <message>
        <source>Bottle Filler (PackML)</source>
        <translation>Llenadora de botellas (PackML)</translation>
    </message>
    <message>
        <source>A PackML unit with Production and Manual modes and a GRAFCET in Resetting, Starting, Execute, Stopping and Aborting</source>
        <translation>Una unidad PackML con los modos Production y Manual y un GRAFCET en Resetting, Starting, Execute, Stopping y Aborting</translation>
    </message>
</context>
<context>
    <name>FaultMenu</name>
    <message>
        <source>Fault not injected</source>
        <translation>Fallo no inyectado</translation>
    </message>
    <message>
        <source>stuck at TRUE</source>
        <extracomment>a fault of a sensor of the virtual machine, shown beside its value</extracomment>
        <translation>bloqueado en TRUE</translation>
    </message>
    <message>
        <source>stuck at FALSE</source>
        <translation>bloqueado en FALSE</translation>
    </message>
    <message>
        <source>flickering</source>
        <translation>intermitente</translation>
    </message>
    <message>
        <source>stuck TRUE</source>
        <extracomment>a sensor&apos;s fault where space is short (the Machine tab); TRUE and FALSE stay as they are</extracomment>
        <translation>bloqueado TRUE</translation>
    </message>
    <message>
        <source>stuck FALSE</source>
        <translation>bloqueado FALSE</translation>
    </message>
    <message>
        <source>flicker</source>
        <translation>intermitente</translation>
    </message>
    <message>
        <source>Fault of %1</source>
        <extracomment>%1: a sensor variable of the virtual machine
----------
%1: a cylinder or conveyor of the virtual machine</extracomment>
        <translation>Fallo de %1</translation>
    </message>
    <message>
        <source>Stuck at &amp;TRUE</source>
        <translation>Bloqueado en &amp;TRUE</translation>
    </message>
    <message>
        <source>Stuck at &amp;FALSE</source>
        <translation>Bloqueado en &amp;FALSE</translation>
    </message>
    <message>
        <source>F&amp;licker</source>
        <translation>&amp;Intermitente</translation>
    </message>
    <message>
        <source>&amp;Clear Fault</source>
        <translation>&amp;Borrar el fallo</translation>
    </message>
    <message>
        <source>Clear &amp;Jam</source>
        <translation>&amp;Desatascar</translation>
    </message>
    <message>
        <source>&amp;Jam</source>
        <translation>&amp;Atascar</translation>
    </message>
</context>
<context>
    <name>GrafcetClipboard</name>
    <message>
        <source>The clipboard holds no GRAFCET steps</source>
        <translation>El portapapeles no contiene etapas de GRAFCET</translation>
    </message>
    <message>
        <source>Nothing pasted: the GRAFCET steps on the clipboard are damaged (%1)</source>
        <extracomment>%1 what is wrong in the clipboard&apos;s data (in English), with where when known</extracomment>
        <translation>No se ha pegado nada: las etapas de GRAFCET del portapapeles están dañadas (%1)</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Etapa %1</translation>
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
        <translation>GRAFCET anidado dibujado con GG Studio</translation>
    </message>
</context>
<context>
    <name>InitialStepRule</name>
    <message>
        <source>%1 is the initial step, which cannot be hidden; make another step initial first</source>
        <extracomment>%1 is a GEMMA step, e.g. A1</extracomment>
        <translation>%1 es la etapa inicial, que no se puede ocultar; haga primero inicial otra etapa</translation>
    </message>
    <message>
        <source>%1 is hidden and cannot be the initial step; show it first</source>
        <extracomment>%1 is a GEMMA step, e.g. A3</extracomment>
        <translation>%1 está oculta y no puede ser la etapa inicial; muéstrela primero</translation>
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
        <translation>(sin cablear)</translation>
    </message>
    <message>
        <source>%1, jammed</source>
        <extracomment>%1: the kind of a machine component (&quot;Double-acting cylinder&quot;), which a fault has stopped</extracomment>
        <translation>%1, atascado</translation>
    </message>
</context>
<context>
    <name>MachineDiagnosticText</name>
    <message>
        <source>an input</source>
        <translation>una entrada</translation>
    </message>
    <message>
        <source>an output</source>
        <translation>una salida</translation>
    </message>
    <message>
        <source>an internal variable</source>
        <translation>una variable interna</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal names &apos;%3&apos;, which is no variable of the model.</source>
        <extracomment>%1: a machine component; %2: its role (extend, retracted...); %3: a name</extracomment>
        <translation>La señal %2 de %1 nombra &apos;%3&apos;, que no es una variable del modelo.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal is %3, %4; it needs %5.</source>
        <extracomment>%1: a machine component; %2: its role; %3: a variable; %4, %5: &quot;an input&quot;, &quot;an output&quot;...</extracomment>
        <translation>La señal %2 de %1 es %3, %4; necesita %5.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal is %3, of type %4; a machine signal is BOOL.</source>
        <extracomment>%4: an IEC type (INT)</extracomment>
        <translation>La señal %2 de %1 es %3, de tipo %4; una señal de la máquina es BOOL.</translation>
    </message>
    <message>
        <source>%3 is wired to %1&apos;s %2 signal and to %4&apos;s %5 signal: an input has one source.</source>
        <extracomment>%1, %4: machine components; %2, %5: their roles; %3: the input both are wired to</extracomment>
        <translation>%3 está cableada a la señal %2 de %1 y a la señal %5 de %4: una entrada tiene una sola fuente.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal %3 is driven by no action of the program: the component never moves.</source>
        <translation>La señal %2 (%3) de %1 no la acciona ninguna acción del programa: el componente nunca se mueve.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 is %3: out of range (travel times 1 to 3600000 ms, delays 0 to 3600000 ms, parts 0 to 1000000000).</source>
        <extracomment>%2: a parameter (extendMs, onDelayMs, parts); %3: its value</extracomment>
        <translation>%2 de %1 vale %3: fuera de rango (tiempos de recorrido de 1 a 3600000 ms, retardos de 0 a 3600000 ms, piezas de 0 a 1000000000).</translation>
    </message>
    <message>
        <source>%1 has no variable for its %2 signal.</source>
        <translation>%1 no tiene variable para su señal %2.</translation>
    </message>
    <message>
        <source>%1 feeds &apos;%2&apos;, which is no conveyor of the machine.</source>
        <translation>%1 alimenta &apos;%2&apos;, que no es un transportador de la máquina.</translation>
    </message>
</context>
<context>
    <name>MachineText</name>
    <message>
        <source>Double-acting cylinder</source>
        <translation>Cilindro de doble efecto</translation>
    </message>
    <message>
        <source>Single-acting cylinder</source>
        <translation>Cilindro de simple efecto</translation>
    </message>
    <message>
        <source>Conveyor</source>
        <translation>Cinta transportadora</translation>
    </message>
    <message>
        <source>Lamp</source>
        <translation>Piloto</translation>
    </message>
    <message>
        <source>Push button</source>
        <translation>Pulsador</translation>
    </message>
    <message>
        <source>Selector</source>
        <translation>Selector</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Parada de emergencia</translation>
    </message>
    <message>
        <source>Delayed sensor</source>
        <translation>Sensor temporizado</translation>
    </message>
    <message>
        <source>Part source</source>
        <translation>Fuente de piezas</translation>
    </message>
    <message>
        <source>extend</source>
        <translation>extender</translation>
    </message>
    <message>
        <source>retract</source>
        <translation>retraer</translation>
    </message>
    <message>
        <source>retracted</source>
        <translation>retraído</translation>
    </message>
    <message>
        <source>extended</source>
        <translation>extendido</translation>
    </message>
    <message>
        <source>run</source>
        <translation>marcha</translation>
    </message>
    <message>
        <source>part present</source>
        <translation>pieza presente</translation>
    </message>
    <message>
        <source>lamp</source>
        <translation>piloto</translation>
    </message>
    <message>
        <source>input</source>
        <translation>entrada</translation>
    </message>
    <message>
        <source>output</source>
        <translation>salida</translation>
    </message>
    <message>
        <source>sensor</source>
        <translation>sensor</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>vacío</translation>
    </message>
    <message>
        <source>Extend time (ms)</source>
        <translation>Tiempo de extensión (ms)</translation>
    </message>
    <message>
        <source>Retract time (ms)</source>
        <translation>Tiempo de retracción (ms)</translation>
    </message>
    <message>
        <source>Travel time (ms)</source>
        <translation>Tiempo de recorrido (ms)</translation>
    </message>
    <message>
        <source>On delay (ms)</source>
        <translation>Retardo a la conexión (ms)</translation>
    </message>
    <message>
        <source>Off delay (ms)</source>
        <translation>Retardo a la desconexión (ms)</translation>
    </message>
    <message>
        <source>Parts</source>
        <translation>Piezas</translation>
    </message>
    <message>
        <source>Normally closed</source>
        <translation>Normalmente cerrado</translation>
    </message>
    <message>
        <source>Normally open</source>
        <translation>Normalmente abierto</translation>
    </message>
</context>
<context>
    <name>MoveGrafcetActionCommand</name>
    <message>
        <source>Move action %1 of %2 step %3 up</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Subir la acción %1 de la etapa %3 de %2</translation>
    </message>
    <message>
        <source>Move action %1 of %2 step %3 down</source>
        <translation>Bajar la acción %1 de la etapa %3 de %2</translation>
    </message>
</context>
<context>
    <name>MovePropertyCommand</name>
    <message>
        <source>Move property %1</source>
        <translation>Mover la propiedad %1</translation>
    </message>
</context>
<context>
    <name>MoveVariableCommand</name>
    <message>
        <source>Move variable %1</source>
        <translation>Mover la variable %1</translation>
    </message>
</context>
<context>
    <name>NestedProblemText</name>
    <message>
        <source>the receptivity of T%2 of %1</source>
        <extracomment>%1: a GEMMA step; %2: the number of a transition of its nested GRAFCET</extracomment>
        <translation>la receptividad de T%2 de %1</translation>
    </message>
    <message>
        <source>action %3 of step %2 of %1</source>
        <extracomment>%1: a GEMMA step; %2: a nested step&apos;s number; %3: the action&apos;s position in its list, from 1</extracomment>
        <translation>la acción %3 de la etapa %2 de %1</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is not a declared variable.</source>
        <translation>En %1: &apos;%2&apos; no es una variable declarada.</translation>
    </message>
    <message>
        <source>In %1: a continuous action is N V or V IF &lt;condition&gt;.</source>
        <translation>En %1: una acción continua es N V o V IF &lt;condición&gt;.</translation>
    </message>
    <message>
        <source>In %1: a stored action is S V, R V or V := &lt;expression&gt;.</source>
        <translation>En %1: una acción memorizada es S V, R V o V := &lt;expresión&gt;.</translation>
    </message>
    <message>
        <source>Syntax error in %1: %2.</source>
        <translation>Error de sintaxis en %1: %2.</translation>
    </message>
    <message>
        <source>Type error in %1: %2.</source>
        <translation>Error de tipo en %1: %2.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is %3; this action needs a BOOL variable.</source>
        <extracomment>%3: an IEC type name (INT)</extracomment>
        <translation>En %1: &apos;%2&apos; es %3; esta acción necesita una variable BOOL.</translation>
    </message>
    <message>
        <source>In %1: %4 does not fit &apos;%2&apos; (%3): it cannot be assigned to it.</source>
        <extracomment>%2: the target variable; %3: its type; %4: the value as written</extracomment>
        <translation>En %1: %4 no corresponde a &apos;%2&apos; (%3): no se le puede asignar.</translation>
    </message>
    <message>
        <source>In %1: %2 names step %3, which the GRAFCET of %4 does not have.</source>
        <extracomment>%2: a step activity as written (X9); %3: its step number; %4: the GEMMA step</extracomment>
        <translation>En %1: %2 nombra la etapa %3, que el GRAFCET de %4 no tiene.</translation>
    </message>
    <message>
        <source>In %1: %2 is longer than %3, the longest duration an IEC TIME (a TON preset) holds.</source>
        <extracomment>%2: a duration as written (25d/X1); %3: the longest IEC TIME</extracomment>
        <translation>En %1: %2 es más largo que %3, la duración más larga que cabe en un TIME IEC (la consigna de un TON).</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; divides by zero: on the PLC an integer division or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / 0)</extracomment>
        <translation>En %1: &apos;%2&apos; divide por cero: en el PLC una división entera o MOD por cero detiene la tarea con un fallo, y una REAL da INF o NaN.</translation>
    </message>
    <message>
        <source>In %1: the divisor of &apos;%2&apos; can be zero: an integer division or MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / Batch)</extracomment>
        <translation>En %1: el divisor de &apos;%2&apos; puede ser cero: una división entera o MOD por cero detiene el PLC con un fallo (y la simulación), una REAL da INF o NaN.</translation>
    </message>
    <message>
        <source>In %1: %2 is an edge on a variable that is not BOOL.</source>
        <extracomment>%2: an edge as written (RE Level)</extracomment>
        <translation>En %1: %2 es un flanco sobre una variable que no es BOOL.</translation>
    </message>
    <message>
        <source>In %1: %2 is for receptivities only: an action cannot read an edge or a step duration.</source>
        <translation>En %1: %2 es solo para receptividades: una acción no puede leer un flanco ni una duración de etapa.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is an input: it is read from the machine, actions never write it.</source>
        <translation>En %1: &apos;%2&apos; es una entrada: se lee de la máquina, las acciones nunca la escriben.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is %3; a continuous action needs a BOOL variable.</source>
        <extracomment>%3: an IEC type name (INT)</extracomment>
        <translation>En %1: &apos;%2&apos; es %3; una acción continua necesita una variable BOOL.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is also driven by continuous actions; a variable has either continuous or stored actions (the stored one is not generated).</source>
        <translation>En %1: &apos;%2&apos; también la mandan acciones continuas; una variable tiene acciones continuas o memorizadas (la memorizada no se genera).</translation>
    </message>
    <message>
        <source>In %1: invalid variable name: %2.</source>
        <translation>En %1: nombre de variable no válido: %2.</translation>
    </message>
    <message>
        <source>In %1: the condition reads &apos;%2&apos;, a continuous output of the same GRAFCET.</source>
        <translation>En %1: la condición lee &apos;%2&apos;, una salida continua del mismo GRAFCET.</translation>
    </message>
    <message>
        <source>The receptivity of T%2 of %1 is empty: write TRUE for a transition that is always ready.</source>
        <translation>La receptividad de T%2 de %1 está vacía: escriba TRUE para una transición siempre lista.</translation>
    </message>
</context>
<context>
    <name>OperatorItem</name>
    <message>
        <source>switched on</source>
        <translation>activado</translation>
    </message>
    <message>
        <source>switched off</source>
        <translation>desactivado</translation>
    </message>
    <message>
        <source>pressed</source>
        <translation>pulsado</translation>
    </message>
    <message>
        <source>released</source>
        <translation>soltado</translation>
    </message>
</context>
<context>
    <name>PackMLDiagnosticText</name>
    <message>
        <source>The model has no unit mode.</source>
        <translation>El modelo no tiene ningún modo de unidad.</translation>
    </message>
    <message>
        <source>The initial mode %1 is not a unit mode of the model.</source>
        <translation>El modo inicial %1 no es un modo de unidad del modelo.</translation>
    </message>
    <message>
        <source>The initial state %1 is not Stopped, Idle or Aborted.</source>
        <translation>El estado inicial %1 no es Stopped, Idle ni Aborted.</translation>
    </message>
    <message>
        <source>The model&apos;s name &apos;%1&apos; cannot name the PROGRAM (it is no IEC identifier, or the generated code or a variable takes it): the PROGRAM is named %2.</source>
        <translation>El nombre del modelo «%1» no puede nombrar el PROGRAM (no es un identificador IEC, o el código generado o una variable ya lo usa): el PROGRAM se llama %2.</translation>
    </message>
    <message>
        <source>Unit mode %1 is outside 1..31 (PackTags UnitMode).</source>
        <translation>El modo de unidad %1 está fuera de 1..31 (PackTags UnitMode).</translation>
    </message>
    <message>
        <source>Unit mode %1 is given twice.</source>
        <translation>El modo de unidad %1 aparece dos veces.</translation>
    </message>
    <message>
        <source>Unit mode %1 is named %2, not &apos;%3&apos;.</source>
        <extracomment>%2: the fixed name of a base mode (Production, Maintenance, Manual)</extracomment>
        <translation>El modo de unidad %1 se llama %2, no «%3».</translation>
    </message>
    <message>
        <source>The name &apos;%2&apos; of unit mode %1 is not an IEC identifier, and it becomes part of the names of function blocks.</source>
        <translation>El nombre «%2» del modo de unidad %1 no es un identificador IEC, y forma parte de los nombres de los bloques de función.</translation>
    </message>
    <message>
        <source>The name &apos;%2&apos; of unit mode %1 is one the generated code uses.</source>
        <translation>El nombre «%2» del modo de unidad %1 lo usa el código generado.</translation>
    </message>
    <message>
        <source>Unit mode %1 is named &apos;%2&apos;, as mode %3 is (ignoring case).</source>
        <translation>El modo de unidad %1 se llama «%2», como el modo %3 (sin distinguir mayúsculas).</translation>
    </message>
    <message>
        <source>Mode %1 lists %2 as disabled, which every unit needs: ignored.</source>
        <translation>El modo %1 marca %2 como desactivado, y toda unidad lo necesita: se ignora.</translation>
    </message>
    <message>
        <source>Mode %1 lists %2 as disabled, but it stays enabled while %3 is enabled.</source>
        <extracomment>%3: the enabled acting states of the loop (Holding, Unholding)</extracomment>
        <translation>El modo %1 marca %2 como desactivado, pero sigue activado mientras %3 esté activado.</translation>
    </message>
    <message>
        <source>Mode %1 allows a mode change in %2, an acting state, half-way through its GRAFCET: ignored.</source>
        <translation>El modo %1 permite un cambio de modo en %2, un estado de acción, a mitad de su GRAFCET: se ignora.</translation>
    </message>
    <message>
        <source>Mode %1 allows a mode change in %2, which it disables: no effect.</source>
        <translation>El modo %1 permite un cambio de modo en %2, que desactiva: no tiene efecto.</translation>
    </message>
    <message>
        <source>Mode %1 can never be current: it is not the initial mode, and no state allows a change into it from another mode.</source>
        <translation>El modo %1 nunca puede ser el actual: no es el modo inicial y ningún estado permite cambiar a él desde otro modo.</translation>
    </message>
    <message>
        <source>In mode %1, no sequence of transitions leads to Execute from where the mode begins (counting a State Complete only where the state&apos;s GRAFCET writes Complete).</source>
        <translation>En el modo %1, ninguna secuencia de transiciones lleva a Execute desde donde empieza el modo (un State Complete solo cuenta donde el GRAFCET del estado escribe Complete).</translation>
    </message>
    <message>
        <source>In mode %1, no sequence of transitions reaches %2 from where the mode begins: it is never active.</source>
        <translation>En el modo %1, ninguna secuencia de transiciones alcanza %2 desde donde empieza el modo: nunca está activo.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: Aborting never writes Complete: nothing leaves Aborting, so the unit can never reach Aborted.</source>
        <translation>El GRAFCET de %1: Aborting nunca escribe Complete: nada sale de Aborting, así que la unidad nunca puede llegar a Aborted.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: %2 never writes Complete: only Stop or Abort leave the state.</source>
        <translation>El GRAFCET de %1: %2 nunca escribe Complete: solo Stop o Abort salen del estado.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: %2 is kept, but the mode disables the state: it generates no code.</source>
        <translation>El GRAFCET de %1: %2 se conserva, pero el modo desactiva el estado: no genera código.</translation>
    </message>
    <message>
        <source>there is no mode %1</source>
        <translation>no existe el modo %1</translation>
    </message>
    <message>
        <source>that is the mode itself</source>
        <translation>es el propio modo</translation>
    </message>
    <message>
        <source>mode %1 has no GRAFCET of its own there</source>
        <translation>el modo %1 no tiene ahí un GRAFCET propio</translation>
    </message>
    <message>
        <source>%1: %2 runs the same GRAFCET as mode %3, but %4.</source>
        <extracomment>%4: why (there is no mode 9, that is the mode itself, ...)</extracomment>
        <translation>%1: %2 ejecuta el mismo GRAFCET que el modo %3, pero %4.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: Execute writes Complete, which nothing reads in the 2022 edition: use the Complete command.</source>
        <translation>El GRAFCET de %1: Execute escribe Complete, que nada lee en la edición 2022: use el comando Complete.</translation>
    </message>
    <message>
        <source>The condition of %1 is empty: write FALSE for a command that comes only through CntrlCmd.</source>
        <translation>La condición de %1 está vacía: escriba FALSE para un comando que solo llega por CntrlCmd.</translation>
    </message>
    <message>
        <source>Command %2 has the same condition as command %1: one rising edge issues both, and only the first in priority acts.</source>
        <translation>El comando %2 tiene la misma condición que el comando %1: un mismo flanco ascendente emite ambos y solo actúa el primero en prioridad.</translation>
    </message>
    <message>
        <source>The request of mode %2 has the same condition as the request of mode %1: one rising edge issues both, and only the first in priority acts.</source>
        <translation>La petición del modo %2 tiene la misma condición que la petición del modo %1: un mismo flanco ascendente emite ambas y solo actúa la primera en prioridad.</translation>
    </message>
    <message>
        <source>The condition of %1 reads the output &apos;%2&apos;: commands and mode requests come from an operator, a line controller or an alarm, so read an input or an internal variable.</source>
        <translation>La condición de %1 lee la salida «%2»: los comandos y las peticiones de modo vienen de un operador, de un controlador de línea o de una alarma, así que lea una entrada o una variable interna.</translation>
    </message>
    <message>
        <source>No enabled state of any mode accepts the command %1: it generates no code.</source>
        <translation>Ningún estado activado de ningún modo acepta el comando %1: no genera código.</translation>
    </message>
    <message>
        <source>The Complete command exists in the 2022 edition only: its setting is ignored in this 2015 model.</source>
        <translation>El comando Complete solo existe en la edición 2022: su ajuste se ignora en este modelo 2015.</translation>
    </message>
    <message>
        <source>The option completeInSuspendedHeld is for the 2022 edition only: it is ignored in this 2015 model.</source>
        <translation>La opción completeInSuspendedHeld es solo para la edición 2022: se ignora en este modelo 2015.</translation>
    </message>
    <message>
        <source>a step activity</source>
        <translation>una actividad de etapa</translation>
    </message>
    <message>
        <source>a step duration</source>
        <translation>una duración de etapa</translation>
    </message>
    <message>
        <source>an edge</source>
        <translation>un flanco</translation>
    </message>
    <message>
        <source>The condition of %1 uses %2 (&apos;%3&apos;), which only the texts of nested GRAFCETs have; a command or request is already the rising edge of its condition.</source>
        <extracomment>%2: what the condition uses (a step activity, an edge...); %3: the text as written</extracomment>
        <translation>La condición de %1 usa %2 («%3»), que solo tienen los textos de los GRAFCET anidados; un comando o una petición ya es el flanco ascendente de su condición.</translation>
    </message>
    <message>
        <source>mode %1</source>
        <extracomment>A unit mode of a PackML model: &quot;mode Manual&quot;</extracomment>
        <translation>modo %1</translation>
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
        <translation>petición del modo %1</translation>
    </message>
    <message>
        <source>The variable name &apos;%1&apos; is one the generated PackML code uses (PackTags, the state machine, the function blocks or the program %2).</source>
        <translation>El nombre de variable «%1» lo usa el código PackML generado (PackTags, la máquina de estados, los bloques de función o el programa %2).</translation>
    </message>
</context>
<context>
    <name>PackmlChartExport</name>
    <message>
        <source>PackML chart drawn by GG Studio</source>
        <translation>Diagrama PackML dibujado por GG Studio</translation>
    </message>
    <message>
        <source>Unit mode %1</source>
        <translation>Modo de unidad %1</translation>
    </message>
</context>
<context>
    <name>PackmlSimulationText</name>
    <message>
        <source>%1 cannot be entered in %2: %3</source>
        <extracomment>%1: a unit mode (Manual), %2: a PackML state (Execute), %3: why</extracomment>
        <translation>%1 no puede activarse en %2: %3</translation>
    </message>
    <message>
        <source>%1; %2 grants it in no state</source>
        <extracomment>%1: a refusal, %2: the current unit mode</extracomment>
        <translation>%1; %2 no lo concede en ningún estado</translation>
    </message>
    <message>
        <source>%1; it can be entered in %2</source>
        <extracomment>%1: a refusal, %2: PackML states (&quot;Stopped, Idle, Aborted&quot;)</extracomment>
        <translation>%1; puede activarse en %2</translation>
    </message>
    <message>
        <source>%1 allows no mode change there</source>
        <translation>%1 no permite allí ningún cambio de modo</translation>
    </message>
    <message>
        <source>%1 disables this state</source>
        <translation>%1 desactiva este estado</translation>
    </message>
    <message>
        <source>%1 is not granted: %2, lower-numbered, is granted in the same scan</source>
        <extracomment>%2: the unit mode granted instead</extracomment>
        <translation>%1 no se concede: %2, de número menor, se concede en el mismo ciclo</translation>
    </message>
    <message>
        <source>%1 is requested: it is already the current mode</source>
        <translation>%1 se solicita: ya es el modo actual</translation>
    </message>
    <message>
        <source>%1 names no unit mode</source>
        <translation>%1 no designa ningún modo de la unidad</translation>
    </message>
    <message>
        <source>the SC of %1</source>
        <translation>el SC de %1</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2</source>
        <extracomment>%1: a PackML command (Hold), %2: a state (Idle)</extracomment>
        <translation>%1 no se acepta en %2</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2 in %3: the mode disables where it leads</source>
        <extracomment>%1: a command, %2: a state, %3: a unit mode</extracomment>
        <translation>%1 no se acepta en %2 en %3: el modo desactiva el estado al que lleva</translation>
    </message>
    <message>
        <source>%1 is pre-empted by %2</source>
        <extracomment>%2: the transition that fired instead (&quot;Execute-Stop-&gt;Stopped&quot;)</extracomment>
        <translation>%1 queda anulado por %2</translation>
    </message>
    <message>
        <source>%1 names no command</source>
        <translation>%1 no designa ningún comando</translation>
    </message>
    <message>
        <source>the receptivity of T%1 of %2</source>
        <extracomment>%1: a transition number of a nested GRAFCET, %2: its function block instance</extracomment>
        <translation>la receptividad de T%1 de %2</translation>
    </message>
    <message>
        <source>action %1 of step %2 of %3</source>
        <extracomment>%1: an action&apos;s position, %2: a step number, %3: a function block instance</extracomment>
        <translation>la acción %1 de la etapa %2 de %3</translation>
    </message>
    <message>
        <source>the condition of the %1 command</source>
        <extracomment>%1: a PackML command (Start)</extracomment>
        <translation>la condición del comando %1</translation>
    </message>
    <message>
        <source>the request condition of mode %1</source>
        <extracomment>%1: a unit mode (Manual)</extracomment>
        <translation>la condición de solicitud del modo %1</translation>
    </message>
    <message>
        <source>cannot set %1: %2</source>
        <extracomment>%1: a variable or instance, %2: why (from the simulator)</extracomment>
        <translation>no se puede asignar %1: %2</translation>
    </message>
    <message>
        <source>expected state %1, the state is %2</source>
        <translation>se esperaba el estado %1, el estado es %2</translation>
    </message>
    <message>
        <source>expected mode %1, the mode is %2</source>
        <translation>se esperaba el modo %1, el modo es %2</translation>
    </message>
    <message>
        <source>expected %1 = %2, it is %3</source>
        <translation>se esperaba %1 = %2, es %3</translation>
    </message>
    <message>
        <source>expected %1 to fire, no transition fired</source>
        <translation>se esperaba que %1 se franqueara, no se franqueó ninguna transición</translation>
    </message>
    <message>
        <source>expected %1 to fire, %2 fired</source>
        <translation>se esperaba que %1 se franqueara, se franqueó %2</translation>
    </message>
    <message>
        <source>expected no transition to fire, %1 fired</source>
        <translation>no se esperaba ningún franqueo, se franqueó %1</translation>
    </message>
    <message>
        <source>scan %1: %2</source>
        <extracomment>%1: a scan number, %2: what did not hold</extracomment>
        <translation>ciclo %1: %2</translation>
    </message>
    <message>
        <source>Stopped at scan %1: integer division by zero in %2 (%3 in &apos;%4&apos;). On the PLC the task stops with a fault; Reset to run again.</source>
        <extracomment>%1: a scan number, %2: where (a condition, a receptivity, an action), %3: the division as written, %4: the text</extracomment>
        <translation>Detenido en el ciclo %1: división entera por cero en %2 (%3 en «%4»). En el PLC la tarea se detiene con un fallo; reinicie para volver a ejecutar.</translation>
    </message>
    <message>
        <source>%1: granted</source>
        <extracomment>a unit mode request that the mode manager granted</extracomment>
        <translation>%1: concedido</translation>
    </message>
    <message>
        <source>%1: not granted</source>
        <translation>%1: no concedido</translation>
    </message>
    <message>
        <source>%1: fired %2</source>
        <extracomment>%1: a command, %2: the transition it fired (&quot;Idle-Start-&gt;Execute&quot;)</extracomment>
        <translation>%1: se franqueó %2</translation>
    </message>
    <message>
        <source>%1: no transition fired</source>
        <translation>%1: no se franqueó ninguna transición</translation>
    </message>
</context>
<context>
    <name>PackmlTexts</name>
    <message>
        <source>Wait state</source>
        <translation>Estado de espera</translation>
    </message>
    <message>
        <source>Acting state</source>
        <translation>Estado activo</translation>
    </message>
    <message>
        <source>Dual state: acts and waits for a command</source>
        <translation>Estado dual: actúa y espera una orden</translation>
    </message>
    <message>
        <source>Clears the faults that led to Aborted, then goes to Stopped.</source>
        <translation>Borra los fallos que llevaron a Aborted y pasa a Stopped.</translation>
    </message>
    <message>
        <source>Powered and stationary; waits for Reset.</source>
        <translation>Alimentada y parada; espera Reset.</translation>
    </message>
    <message>
        <source>Prepares the unit to produce, then goes to Execute.</source>
        <translation>Prepara la unidad para producir y pasa a Execute.</translation>
    </message>
    <message>
        <source>Reset and ready; waits for Start.</source>
        <translation>Restablecida y lista; espera Start.</translation>
    </message>
    <message>
        <source>Paused by a condition outside the unit (starved, blocked); waits for Unsuspend.</source>
        <translation>En pausa por una condición ajena a la unidad (falta de material, bloqueo); espera Unsuspend.</translation>
    </message>
    <message>
        <source>Produces; waits for Hold, Suspend or the end of the batch.</source>
        <translation>Produce; espera Hold, Suspend o el fin del lote.</translation>
    </message>
    <message>
        <source>Brings the unit to a controlled stop, then goes to Stopped.</source>
        <translation>Lleva la unidad a una parada controlada y pasa a Stopped.</translation>
    </message>
    <message>
        <source>Brings the unit to a quick safe stop, then goes to Aborted.</source>
        <translation>Lleva la unidad a una parada rápida y segura y pasa a Aborted.</translation>
    </message>
    <message>
        <source>Stopped after an abort; waits for Clear.</source>
        <translation>Parada tras un aborto; espera Clear.</translation>
    </message>
    <message>
        <source>Brings production to a controlled pause for an internal reason, then goes to Held.</source>
        <translation>Lleva la producción a una pausa controlada por una causa interna y pasa a Held.</translation>
    </message>
    <message>
        <source>Paused for an internal reason; waits for Unhold.</source>
        <translation>En pausa por una causa interna; espera Unhold.</translation>
    </message>
    <message>
        <source>Prepares to resume production after Held, then goes to Execute.</source>
        <translation>Prepara la reanudación de la producción tras Held y pasa a Execute.</translation>
    </message>
    <message>
        <source>Brings production to a controlled pause for an outside reason, then goes to Suspended.</source>
        <translation>Lleva la producción a una pausa controlada por una causa externa y pasa a Suspended.</translation>
    </message>
    <message>
        <source>Prepares to resume production after Suspended, then goes to Execute.</source>
        <translation>Prepara la reanudación de la producción tras Suspended y pasa a Execute.</translation>
    </message>
    <message>
        <source>Brings the unit to its ready state, then goes to Idle.</source>
        <translation>Lleva la unidad a su estado listo y pasa a Idle.</translation>
    </message>
    <message>
        <source>Ends the batch in order, then goes to Complete.</source>
        <translation>Termina el lote en orden y pasa a Complete.</translation>
    </message>
    <message>
        <source>The batch is complete; waits for Reset.</source>
        <translation>El lote está terminado; espera Reset.</translation>
    </message>
    <message>
        <source>Reset: make the unit ready to start again.</source>
        <translation>Reset: dejar la unidad lista para arrancar de nuevo.</translation>
    </message>
    <message>
        <source>Start: begin producing.</source>
        <translation>Start: empezar a producir.</translation>
    </message>
    <message>
        <source>Stop: bring the unit to a controlled stop.</source>
        <translation>Stop: llevar la unidad a una parada controlada.</translation>
    </message>
    <message>
        <source>Hold: pause production for an internal reason.</source>
        <translation>Hold: pausar la producción por una causa interna.</translation>
    </message>
    <message>
        <source>Unhold: resume production after a Hold.</source>
        <translation>Unhold: reanudar la producción tras un Hold.</translation>
    </message>
    <message>
        <source>Suspend: pause production for an outside reason.</source>
        <translation>Suspend: pausar la producción por una causa externa.</translation>
    </message>
    <message>
        <source>Unsuspend: resume production after a Suspend.</source>
        <translation>Unsuspend: reanudar la producción tras un Suspend.</translation>
    </message>
    <message>
        <source>Abort: stop the unit at once, safely.</source>
        <translation>Abort: parar la unidad de inmediato, con seguridad.</translation>
    </message>
    <message>
        <source>Clear: clear the faults after an Abort.</source>
        <translation>Clear: borrar los fallos tras un Abort.</translation>
    </message>
    <message>
        <source>Complete: end the batch.</source>
        <translation>Complete: terminar el lote.</translation>
    </message>
</context>
<context>
    <name>PackmlVerificationText</name>
    <message>
        <source>In %1, Execute, entered again from the Hold or Suspend loop, started afresh instead of resuming where it was paused.</source>
        <translation>En %1, Execute, reactivado desde el bucle Hold o Suspend, empezó de cero en lugar de reanudar donde se había detenido.</translation>
    </message>
    <message>
        <source>In %1, Execute resumed where it should have started afresh from its initial situation.</source>
        <translation>En %1, Execute se reanudó cuando debería haber empezado de cero desde su situación inicial.</translation>
    </message>
    <message>
        <source>In %1, Execute resumed in a situation other than the one it was paused in.</source>
        <translation>En %1, Execute se reanudó en una situación distinta de aquella en que se detuvo.</translation>
    </message>
    <message>
        <source>The verification was not exhaustive (its time or size limit, timers or numeric inputs it explores only in part): stuck states, states never active and commands never accepted were not decided, and the absence of other findings is not a proof.</source>
        <translation>La verificación no fue exhaustiva (su límite de tiempo o de tamaño, temporizadores o entradas numéricas que solo explora en parte): los estados bloqueados, los estados nunca activos y los comandos nunca aceptados no se decidieron, y la ausencia de otros hallazgos no es una prueba.</translation>
    </message>
    <message>
        <source>In %1, the GRAFCET of %2 can reach a situation from which Complete never becomes TRUE: only Stop or Abort then leave %2.</source>
        <translation>En %1, el GRAFCET de %2 puede llegar a una situación desde la que Complete nunca se vuelve TRUE: entonces solo Stop o Abort sacan de %2.</translation>
    </message>
    <message>
        <source>In %1, Aborting can reach a situation from which Aborted is never reached: nothing leaves it.</source>
        <translation>En %1, Aborting puede llegar a una situación desde la que nunca se alcanza Aborted: nada sale de ella.</translation>
    </message>
    <message>
        <source>%2 was active at the end of a scan in %1, a mode that disables it.</source>
        <translation>%2 estaba activo al final de un ciclo en %1, un modo que lo deshabilita.</translation>
    </message>
    <message>
        <source>The mode changed from %1 in %2, a state where this change is not allowed.</source>
        <translation>El modo cambió desde %1 en %2, un estado donde este cambio no está permitido.</translation>
    </message>
    <message>
        <source>%1 is never the current mode.</source>
        <translation>%1 nunca es el modo actual.</translation>
    </message>
    <message>
        <source>%2 is enabled in %1 but never active there.</source>
        <translation>%2 está habilitado en %1 pero nunca está activo allí.</translation>
    </message>
    <message>
        <source>The %1 command is accepted in no reachable configuration.</source>
        <translation>El comando %1 no se acepta en ninguna configuración alcanzable.</translation>
    </message>
    <message>
        <source>In %1, continuous outputs are TRUE at the end of the scan that enters %2: %3.</source>
        <translation>En %1, hay salidas continuas en TRUE al final del ciclo que entra en %2: %3.</translation>
    </message>
    <message>
        <source>In %1, stored outputs can still be TRUE when %2 is entered: %3.</source>
        <translation>En %1, salidas memorizadas pueden seguir en TRUE al entrar en %2: %3.</translation>
    </message>
    <message>
        <source>Stuck states were not decided in %1: timers longer than one cycle may or may not have elapsed, and the ways to Complete found there let timers elapse in an order the PLC&apos;s may not. Every other finding is decided.</source>
        <translation>Los estados bloqueados no se decidieron en %1: los temporizadores más largos que un ciclo pueden haber vencido o no, y los caminos hacia Complete encontrados allí dejan vencer los temporizadores en un orden que los del PLC pueden no seguir. Todos los demás hallazgos están decididos.</translation>
    </message>
</context>
<context>
    <name>PartSourceItem</name>
    <message>
        <source>Unlimited parts</source>
        <translation>Piezas ilimitadas</translation>
    </message>
    <message>
        <source>Parts left: %1</source>
        <translation>Piezas restantes: %1</translation>
    </message>
    <message>
        <source>feeds no conveyor</source>
        <translation>no alimenta ninguna cinta</translation>
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
        <translation>Pegar la variable %1</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n variables</source>
        <translation>
            <numerusform>Pegar %n variable</numerusform>
            <numerusform>Pegar %n variables</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PictureFile</name>
    <message>
        <source>The SVG picture could not be drawn.</source>
        <translation>No se ha podido dibujar la imagen SVG.</translation>
    </message>
    <message>
        <source>Not enough memory for a picture of %1 × %2 pixels.</source>
        <translation>No hay memoria suficiente para una imagen de %1 × %2 píxeles.</translation>
    </message>
    <message>
        <source>The PNG picture could not be encoded.</source>
        <translation>No se ha podido codificar la imagen PNG.</translation>
    </message>
    <message>
        <source>The PDF document could not be drawn.</source>
        <translation>No se ha podido dibujar el documento PDF.</translation>
    </message>
</context>
<context>
    <name>PropertyProblemText</name>
    <message>
        <source>&apos;%1&apos; is not a declared variable</source>
        <translation>&apos;%1&apos; no es una variable declarada</translation>
    </message>
    <message>
        <source>there is no visible GEMMA step &apos;%1&apos;</source>
        <translation>no hay ninguna etapa GEMMA visible &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the step %1 has no nested GRAFCET</source>
        <translation>la etapa %1 no tiene GRAFCET anidado</translation>
    </message>
    <message>
        <source>the GRAFCET of %1 has no step %2</source>
        <translation>el GRAFCET de %1 no tiene etapa %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is only defined when verifying with single faults (Simulation &gt; Verify with Single Faults, with the machine)</source>
        <translation>&apos;%1&apos; solo está definido al verificar con fallos únicos (Simulación &gt; Verificar con fallos únicos, con la máquina)</translation>
    </message>
</context>
<context>
    <name>RecoveryPrompt</name>
    <message>
        <source>an untitled model</source>
        <translation>un modelo sin título</translation>
    </message>
    <message>
        <source>Discard Unsaved Changes</source>
        <translation>Descartar los cambios no guardados</translation>
    </message>
    <message>
        <source>Delete the autosaved copy of %1 for good?</source>
        <translation>¿Eliminar definitivamente la copia guardada automáticamente de %1?</translation>
    </message>
    <message>
        <source>The changes it holds cannot be recovered afterwards.</source>
        <translation>Los cambios que contiene no se podrán recuperar después.</translation>
    </message>
    <message>
        <source>Delete Copy</source>
        <translation>Eliminar la copia</translation>
    </message>
    <message>
        <source>&amp;Keep Copy</source>
        <translation>&amp;Conservar la copia</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Recuperar los cambios no guardados</translation>
    </message>
    <message>
        <source>GG Studio ended without saving %1.</source>
        <translation>GG Studio se cerró sin guardar %1.</translation>
    </message>
    <message>
        <source>Autosave kept a copy on %1. Recover it? You can then save it or discard it.</source>
        <translation>El guardado automático conservó una copia el %1. ¿Recuperarla? Después podrá guardarla o descartarla.</translation>
    </message>
    <message>
        <source>The original file can no longer be identified (moved, deleted or changed since, or named by an older version): saving the recovered model will ask for a file.</source>
        <translation>El archivo original ya no se puede identificar (movido, eliminado o modificado desde entonces, o nombrado por una versión anterior): al guardar el modelo recuperado se le pedirá un archivo.</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Recuperar</translation>
    </message>
    <message>
        <source>Discard…</source>
        <translation>Descartar…</translation>
    </message>
    <message>
        <source>&amp;Not Now</source>
        <translation>A&amp;hora no</translation>
    </message>
    <message>
        <source>The autosaved copy could not be read.</source>
        <translation>No se ha podido leer la copia guardada automáticamente.</translation>
    </message>
</context>
<context>
    <name>RemoveGrafcetActionCommand</name>
    <message>
        <source>Remove action %1 of %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Quitar la acción %1 de la etapa %3 de %2</translation>
    </message>
</context>
<context>
    <name>RemoveMachineComponentCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>Quitar %1</translation>
    </message>
</context>
<context>
    <name>RemoveModeCommand</name>
    <message>
        <source>Remove mode %1</source>
        <translation>Eliminar el modo %1</translation>
    </message>
</context>
<context>
    <name>RemovePropertyCommand</name>
    <message>
        <source>Remove property %1</source>
        <translation>Eliminar la propiedad %1</translation>
    </message>
</context>
<context>
    <name>RemoveVariableCommand</name>
    <message>
        <source>Remove variable %1</source>
        <translation>Eliminar la variable %1</translation>
    </message>
</context>
<context>
    <name>RenameModeCommand</name>
    <message>
        <source>Rename mode %1</source>
        <translation>Renombrar el modo %1</translation>
    </message>
</context>
<context>
    <name>RenameVariableCommand</name>
    <message>
        <source>Rename variable %1 to %2</source>
        <translation>Renombrar la variable %1 a %2</translation>
    </message>
    <message>
        <source>a variable named &apos;%1&apos; already exists (IEC names ignore case)</source>
        <translation>ya existe una variable llamada &apos;%1&apos; (los nombres IEC no distinguen mayúsculas y minúsculas)</translation>
    </message>
</context>
<context>
    <name>RenumberGrafcetStepCommand</name>
    <message>
        <source>Renumber %1 step %2 to %3</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET, %3 its new number</extracomment>
        <translation>Renumerar la etapa %2 de %1 como %3</translation>
    </message>
</context>
<context>
    <name>ResetModelCommand</name>
    <message>
        <source>Reset to template</source>
        <translation>Restablecer la plantilla</translation>
    </message>
</context>
<context>
    <name>SetCommandCommentCommand</name>
    <message>
        <source>Edit comment of command %1</source>
        <translation>Editar el comentario del comando %1</translation>
    </message>
</context>
<context>
    <name>SetCommandConditionCommand</name>
    <message>
        <source>Edit condition of command %1</source>
        <translation>Editar la condición del comando %1</translation>
    </message>
</context>
<context>
    <name>SetConditionCommand</name>
    <message>
        <source>Edit condition of %1</source>
        <translation>Editar la condición de %1</translation>
    </message>
</context>
<context>
    <name>SetCycleTimeCommand</name>
    <message>
        <source>Set cycle time to %1 ms</source>
        <translation>Fijar el tiempo de ciclo en %1 ms</translation>
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
        <translation>Cambiar el dialecto a %1</translation>
    </message>
</context>
<context>
    <name>SetElementsHiddenCommand</name>
    <message numerus="yes">
        <source>Hide %n element(s)</source>
        <translation>
            <numerusform>Ocultar %n elemento</numerusform>
            <numerusform>Ocultar %n elementos</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show %n element(s)</source>
        <translation>
            <numerusform>Mostrar %n elemento</numerusform>
            <numerusform>Mostrar %n elementos</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SetEvolutionRuleCommand</name>
    <message>
        <source>Set evolution rule to until stable</source>
        <translation>Cambiar la regla de evolución a «hasta la estabilidad»</translation>
    </message>
    <message>
        <source>Set evolution rule to one evolution per scan</source>
        <translation>Cambiar la regla de evolución a «una evolución por ciclo»</translation>
    </message>
</context>
<context>
    <name>SetGrafcetActionCommand</name>
    <message>
        <source>Set action %1 of %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Cambiar la acción %1 de la etapa %3 de %2</translation>
    </message>
</context>
<context>
    <name>SetGrafcetChoiceCommand</name>
    <message>
        <source>Give %1 its own GRAFCET in mode %2</source>
        <translation>Dar a %1 su propio GRAFCET en el modo %2</translation>
    </message>
    <message>
        <source>Run in %1 of mode %2 the GRAFCET of mode %3</source>
        <translation>Ejecutar en %1 del modo %2 el GRAFCET del modo %3</translation>
    </message>
    <message>
        <source>Remove the GRAFCET of %1 in mode %2</source>
        <translation>Eliminar el GRAFCET de %1 en el modo %2</translation>
    </message>
</context>
<context>
    <name>SetGrafcetStepCommentCommand</name>
    <message>
        <source>Edit comment of %1 step %2</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET: &quot;Edit comment of F1 step 3&quot;</extracomment>
        <translation>Editar el comentario de la etapa %2 de %1</translation>
    </message>
</context>
<context>
    <name>SetGrafcetStepInitialCommand</name>
    <message>
        <source>Make %1 step %2 initial</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET</extracomment>
        <translation>Hacer inicial la etapa %2 de %1</translation>
    </message>
    <message>
        <source>Make %1 step %2 not initial</source>
        <translation>Hacer no inicial la etapa %2 de %1</translation>
    </message>
</context>
<context>
    <name>SetInitialStepCommand</name>
    <message>
        <source>Make %1 the initial step</source>
        <translation>Hacer de %1 la etapa inicial</translation>
    </message>
</context>
<context>
    <name>SetModeCommentCommand</name>
    <message>
        <source>Edit comment of mode %1</source>
        <translation>Editar el comentario del modo %1</translation>
    </message>
</context>
<context>
    <name>SetModeRequestCommand</name>
    <message>
        <source>Edit request condition of mode %1</source>
        <translation>Editar la condición de solicitud del modo %1</translation>
    </message>
</context>
<context>
    <name>SetModeStatesCommand</name>
    <message>
        <source>Change disabled states of mode %1</source>
        <translation>Cambiar los estados desactivados del modo %1</translation>
    </message>
    <message>
        <source>Change mode-change states of mode %1</source>
        <translation>Cambiar los estados de cambio de modo del modo %1</translation>
    </message>
</context>
<context>
    <name>SetModelNameCommand</name>
    <message>
        <source>Rename model</source>
        <translation>Renombrar el modelo</translation>
    </message>
</context>
<context>
    <name>SetNegatedCommand</name>
    <message>
        <source>Negate %1</source>
        <translation>Negar %1</translation>
    </message>
    <message>
        <source>Remove negation of %1</source>
        <translation>Quitar la negación de %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlInitialModeCommand</name>
    <message>
        <source>Set initial mode to %1</source>
        <translation>Fijar el modo inicial en %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlInitialStateCommand</name>
    <message>
        <source>Set initial state to %1</source>
        <translation>Fijar el estado inicial en %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlOptionsCommand</name>
    <message>
        <source>Change PackML edition and options</source>
        <translation>Cambiar la edición y las opciones PackML</translation>
    </message>
</context>
<context>
    <name>SetPriorityCommand</name>
    <message>
        <source>Set priority of %1 to %2</source>
        <translation>Fijar la prioridad de %1 en %2</translation>
    </message>
</context>
<context>
    <name>SetPropertyCommentCommand</name>
    <message>
        <source>Edit comment of property %1</source>
        <translation>Editar el comentario de la propiedad %1</translation>
    </message>
</context>
<context>
    <name>SetPropertyTextCommand</name>
    <message>
        <source>Edit property %1</source>
        <translation>Editar la propiedad %1</translation>
    </message>
</context>
<context>
    <name>SetReceptivityCommand</name>
    <message>
        <source>Set receptivity of %1 T%2</source>
        <extracomment>%1 is the GEMMA step, %2 the transition number of its nested GRAFCET: &quot;Set receptivity of F1 T3&quot;</extracomment>
        <translation>Cambiar la receptividad de %1 T%2</translation>
    </message>
</context>
<context>
    <name>SetStepCommentCommand</name>
    <message>
        <source>Edit comment of %1</source>
        <translation>Editar el comentario de %1</translation>
    </message>
</context>
<context>
    <name>SetStepHiddenCommand</name>
    <message>
        <source>Hide step %1</source>
        <translation>Ocultar la etapa %1</translation>
    </message>
    <message>
        <source>Show step %1</source>
        <translation>Mostrar la etapa %1</translation>
    </message>
</context>
<context>
    <name>SetStepTypeCommand</name>
    <message>
        <source>macro-step</source>
        <translation>macroetapa</translation>
    </message>
    <message>
        <source>enclosing step</source>
        <translation>etapa encapsulante</translation>
    </message>
    <message>
        <source>simple step</source>
        <translation>etapa simple</translation>
    </message>
    <message>
        <source>Set %1 to %2</source>
        <translation>Convertir %1 en %2</translation>
    </message>
</context>
<context>
    <name>SetTokensCommand</name>
    <message>
        <source>Set tokens of %1</source>
        <translation>Definir las memorias de %1</translation>
    </message>
</context>
<context>
    <name>SetTransitionHiddenCommand</name>
    <message>
        <source>Hide transition %1</source>
        <translation>Ocultar la transición %1</translation>
    </message>
    <message>
        <source>Show transition %1</source>
        <translation>Mostrar la transición %1</translation>
    </message>
</context>
<context>
    <name>SetVariableCommentCommand</name>
    <message>
        <source>Edit comment of %1</source>
        <translation>Editar el comentario de %1</translation>
    </message>
</context>
<context>
    <name>SetVariableDefaultCommand</name>
    <message>
        <source>Set default of %1</source>
        <translation>Cambiar el valor inicial de %1</translation>
    </message>
</context>
<context>
    <name>SetVariableKindCommand</name>
    <message>
        <source>Set kind of %1 to output</source>
        <translation>Cambiar la clase de %1 a salida</translation>
    </message>
    <message>
        <source>Set kind of %1 to internal</source>
        <translation>Cambiar la clase de %1 a interna</translation>
    </message>
    <message>
        <source>Set kind of %1 to input</source>
        <translation>Cambiar la clase de %1 a entrada</translation>
    </message>
</context>
<context>
    <name>SetVariableTypeCommand</name>
    <message>
        <source>Set type of %1 to %2</source>
        <translation>Cambiar el tipo de %1 a %2</translation>
    </message>
</context>
<context>
    <name>SimulationText</name>
    <message>
        <source>%1 = %2 (token of %3)</source>
        <extracomment>a token variable, its value, then the literal it stores (&quot;NOT Stop&quot;)</extracomment>
        <translation>%1 = %2 (memoria de %3)</translation>
    </message>
    <message>
        <source>%1 is %2</source>
        <extracomment>an IEC expression of a condition, then TRUE or FALSE</extracomment>
        <translation>%1 es %2</translation>
    </message>
    <message>
        <source>%1 is %2 (%3)</source>
        <extracomment>an IEC expression of a condition, TRUE or FALSE, then the values it reads (&quot;Speed = 3&quot;)</extracomment>
        <translation>%1 es %2 (%3)</translation>
    </message>
    <message>
        <source>The condition cannot be used: it is FALSE.</source>
        <translation>La condición no se puede usar: vale FALSE.</translation>
    </message>
    <message>
        <source>cannot apply: %1</source>
        <extracomment>%1: why, from the simulator (English)</extracomment>
        <translation>no se puede aplicar: %1</translation>
    </message>
    <message>
        <source>expected step %1, active step is %2</source>
        <translation>se esperaba la etapa %1, la etapa activa es %2</translation>
    </message>
    <message>
        <source>expected step %1, no visible step is active (State = %2)</source>
        <translation>se esperaba la etapa %1, ninguna etapa visible está activa (State = %2)</translation>
    </message>
    <message>
        <source>expected %1 to fire, no transition fired</source>
        <translation>se esperaba que se franqueara %1, no se franqueó ninguna transición</translation>
    </message>
    <message>
        <source>expected %1 to fire, %2 fired</source>
        <translation>se esperaba que se franqueara %1, se franqueó %2</translation>
    </message>
    <message>
        <source>expected no transition to fire, %1 fired</source>
        <translation>no se esperaba que se franqueara ninguna transición, se franqueó %1</translation>
    </message>
    <message>
        <source>expected token %1 = %2, it is %3</source>
        <translation>se esperaba la memoria %1 = %2, vale %3</translation>
    </message>
    <message>
        <source>expected %1 = %2, it is %3</source>
        <extracomment>a variable, the value expected, the value it has</extracomment>
        <translation>se esperaba %1 = %2, vale %3</translation>
    </message>
    <message>
        <source>unknown variable &apos;%1&apos;</source>
        <translation>variable &apos;%1&apos; desconocida</translation>
    </message>
    <message>
        <source>expected Entry = %1, it is %2</source>
        <translation>se esperaba Entry = %1, vale %2</translation>
    </message>
    <message>
        <source>expected %1.Complete = %2, it is %3</source>
        <translation>se esperaba %1.Complete = %2, vale %3</translation>
    </message>
    <message>
        <source>%1.Complete = FALSE</source>
        <extracomment>a macro-step or enclosing step; the transition waits for its Complete</extracomment>
        <translation>%1.Complete = FALSE</translation>
    </message>
    <message>
        <source>%1 fires first</source>
        <extracomment>a transition of higher priority whose condition holds</extracomment>
        <translation>%1 se franquea primero</translation>
    </message>
    <message>
        <source>scan %1: %2</source>
        <extracomment>a scan number, then what differed</extracomment>
        <translation>ciclo %1: %2</translation>
    </message>
    <message>
        <source>expected &apos;at SCAN:&apos; at the start of the line, found %1</source>
        <extracomment>%1: the word found in quotes, or &quot;the end of the line&quot;; &apos;at SCAN:&apos; is scenario syntax</extracomment>
        <translation>se esperaba &apos;at SCAN:&apos; al principio de la línea, se encontró %1</translation>
    </message>
    <message>
        <source>expected a scan number after &apos;at&apos;, found %1</source>
        <translation>se esperaba un número de ciclo después de &apos;at&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected &apos;:&apos; after the scan number, found %1</source>
        <translation>se esperaba &apos;:&apos; después del número de ciclo, se encontró %1</translation>
    </message>
    <message>
        <source>expected &apos;set&apos; or &apos;expect&apos;, found %1</source>
        <translation>se esperaba &apos;set&apos; o &apos;expect&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a variable name or &apos;complete STEP&apos;, found %1</source>
        <translation>se esperaba un nombre de variable o &apos;complete STEP&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;complete&apos;, found %1</source>
        <translation>se esperaba un identificador de etapa después de &apos;complete&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;step&apos;, found %1</source>
        <translation>se esperaba un identificador de etapa después de &apos;step&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a transition id or &apos;none&apos; after &apos;fired&apos;, found %1</source>
        <translation>se esperaba un identificador de transición o &apos;none&apos; después de &apos;fired&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a token name after &apos;token&apos;, found %1</source>
        <translation>se esperaba un nombre de memoria después de &apos;token&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a variable name after &apos;variable&apos;, found %1</source>
        <translation>se esperaba un nombre de variable después de &apos;variable&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the step id, found %1</source>
        <translation>se esperaba &apos;=&apos; después del identificador de etapa, se encontró %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the variable name, found %1</source>
        <translation>se esperaba &apos;=&apos; después del nombre de variable, se encontró %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the token name, found %1</source>
        <translation>se esperaba &apos;=&apos; después del nombre de memoria, se encontró %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after &apos;entry&apos;, found %1</source>
        <translation>se esperaba &apos;=&apos; después de &apos;entry&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a value after &apos;=&apos;, found %1</source>
        <translation>se esperaba un valor después de &apos;=&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected TRUE or FALSE, found %1</source>
        <translation>se esperaba TRUE o FALSE, se encontró %1</translation>
    </message>
    <message>
        <source>expected TRUE, FALSE or auto, found %1</source>
        <extracomment>auto is scenario syntax</extracomment>
        <translation>se esperaba TRUE, FALSE o auto, se encontró %1</translation>
    </message>
    <message>
        <source>expected &apos;,&apos; or the end of the line, found %1</source>
        <translation>se esperaba &apos;,&apos; o el final de la línea, se encontró %1</translation>
    </message>
    <message>
        <source>expected the end of the line, found %1</source>
        <translation>se esperaba el final de la línea, se encontró %1</translation>
    </message>
    <message>
        <source>scans are numbered from 1</source>
        <translation>los ciclos se numeran a partir de 1</translation>
    </message>
    <message>
        <source>%1 is %2: %3</source>
        <extracomment>a variable, its IEC type (INT), then why the value does not fit it</extracomment>
        <translation>%1 es de tipo %2: %3</translation>
    </message>
    <message>
        <source>step %1 is hidden: it does not exist for the simulator</source>
        <translation>la etapa %1 está oculta: no existe para el simulador</translation>
    </message>
    <message>
        <source>unknown step &apos;%1&apos;</source>
        <translation>etapa &apos;%1&apos; desconocida</translation>
    </message>
    <message>
        <source>step %1 is a simple step: it has no Complete</source>
        <translation>la etapa %1 es una etapa simple: no tiene Complete</translation>
    </message>
    <message>
        <source>transition %1 is not effective (it or one of its steps is hidden)</source>
        <translation>la transición %1 no es efectiva (ella o una de sus etapas está oculta)</translation>
    </message>
    <message>
        <source>unknown transition &apos;%1&apos;</source>
        <translation>transición &apos;%1&apos; desconocida</translation>
    </message>
    <message>
        <source>unknown token &apos;%1&apos;</source>
        <translation>memoria &apos;%1&apos; desconocida</translation>
    </message>
    <message>
        <source>the end of the line</source>
        <translation>el final de la línea</translation>
    </message>
    <message>
        <source>invalid UTF-8: a scenario file must be UTF-8 text</source>
        <translation>UTF-8 no válido: un archivo de escenario debe ser texto UTF-8</translation>
    </message>
    <message>
        <source>%1&apos;s Complete is set to two values in scan %2: %3 on line %4, %5 on line %6</source>
        <extracomment>a step id, a scan number, then each value with the line that sets it</extracomment>
        <translation>el Complete de %1 recibe dos valores en el ciclo %2: %3 en la línea %4, %5 en la línea %6</translation>
    </message>
    <message>
        <source>%1 is set to two values in scan %2: %3 on line %4, %5 on line %6</source>
        <extracomment>a variable, a scan number, then each value with the line that sets it</extracomment>
        <translation>%1 recibe dos valores en el ciclo %2: %3 en la línea %4, %5 en la línea %6</translation>
    </message>
    <message>
        <source>expected the active steps of %1 to be %2, they are %3</source>
        <extracomment>%1: a GEMMA step; %2, %3: lists of nested step numbers</extracomment>
        <translation>se esperaban las etapas activas %2 en %1, son %3</translation>
    </message>
    <message>
        <source>expected %1.Unstable = %2, it is %3</source>
        <translation>se esperaba %1.Unstable = %2, vale %3</translation>
    </message>
    <message>
        <source>expected step, fired, token, variable, entry, complete or nested after &apos;expect&apos;, found %1</source>
        <extracomment>step, fired, token, variable, entry and complete are scenario syntax</extracomment>
        <translation>se esperaba step, fired, token, variable, entry, complete o nested tras «expect», se encontró %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;nested&apos;, found %1</source>
        <translation>se esperaba un identificador de etapa tras «nested», se encontró %1</translation>
    </message>
    <message>
        <source>expected &apos;steps&apos; or &apos;unstable&apos; after the step id, found %1</source>
        <extracomment>steps and unstable are scenario syntax</extracomment>
        <translation>se esperaba «steps» o «unstable» tras el identificador de etapa, se encontró %1</translation>
    </message>
    <message>
        <source>expected a step number, found %1</source>
        <translation>se esperaba un número de etapa, se encontró %1</translation>
    </message>
    <message>
        <source>%1 is an output variable: the program writes it, a scenario sets only inputs</source>
        <translation>%1 es una variable de salida: el programa la escribe, un escenario solo fija entradas</translation>
    </message>
    <message>
        <source>%1 is an internal variable: the program writes it, a scenario sets only inputs</source>
        <translation>%1 es una variable interna: el programa la escribe, un escenario solo fija entradas</translation>
    </message>
    <message>
        <source>step %1 has no nested GRAFCET</source>
        <translation>la etapa %1 no tiene GRAFCET anidado</translation>
    </message>
    <message>
        <source>the Complete of %1 comes from its nested GRAFCET: it cannot be set</source>
        <translation>el Complete de %1 viene de su GRAFCET anidado: no se puede fijar</translation>
    </message>
    <message>
        <source>step %1 is not active</source>
        <extracomment>an upstream step of a nested GRAFCET&apos;s transition</extracomment>
        <translation>la etapa %1 no está activa</translation>
    </message>
    <message>
        <source>steps %1 are not active</source>
        <extracomment>the upstream steps of a nested GRAFCET&apos;s transition (&quot;2, 3&quot;)</extracomment>
        <translation>las etapas %1 no están activas</translation>
    </message>
    <message>
        <source>no rising edge of %1 this scan (%1 = %2, at the end of the previous scan %3)</source>
        <extracomment>%1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan</extracomment>
        <translation>sin flanco ascendente de %1 en este ciclo (%1 = %2, al final del ciclo anterior %3)</translation>
    </message>
    <message>
        <source>no falling edge of %1 this scan (%1 = %2, at the end of the previous scan %3)</source>
        <extracomment>%1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan</extracomment>
        <translation>sin flanco descendente de %1 en este ciclo (%1 = %2, al final del ciclo anterior %3)</translation>
    </message>
    <message>
        <source>%1 is FALSE: step %2 active for %3 ms of %4 ms</source>
        <extracomment>%1: a time-dependent receptivity (&quot;5s/X2&quot;); %2: its step; %3 of %4: elapsed and set time in ms</extracomment>
        <translation>%1 es FALSE: etapa %2 activa desde hace %3 ms de %4 ms</translation>
    </message>
    <message>
        <source>%1 is not the active step: its GRAFCET does not evolve in the next scan</source>
        <extracomment>a macro-step or enclosing step</extracomment>
        <translation>%1 no es la etapa activa: su GRAFCET no evoluciona en el próximo ciclo</translation>
    </message>
    <message>
        <source>scan number %1 is too large: a scenario runs at most %2 scans</source>
        <extracomment>%2: the highest scan number a scenario may name</extracomment>
        <translation>el número de ciclo %1 es demasiado grande: un escenario dura como máximo %2 ciclos</translation>
    </message>
    <message>
        <source>expected a command name after &apos;command&apos;, found %1</source>
        <extracomment>&apos;command&apos; is scenario syntax</extracomment>
        <translation>se esperaba un nombre de comando después de &apos;command&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a mode name or number after &apos;mode&apos;, found %1</source>
        <extracomment>&apos;mode&apos; is scenario syntax</extracomment>
        <translation>se esperaba un nombre o número de modo después de &apos;mode&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected a state name after &apos;state&apos;, found %1</source>
        <extracomment>&apos;state&apos; is scenario syntax</extracomment>
        <translation>se esperaba un nombre de estado después de &apos;state&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;</source>
        <translation>comando desconocido &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown unit mode &apos;%1&apos;</source>
        <translation>modo de unidad desconocido &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown state &apos;%1&apos;</source>
        <translation>estado desconocido &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown instance &apos;%1&apos;</source>
        <extracomment>%1: a PackML function block instance (Production_Resetting)</extracomment>
        <translation>instancia desconocida &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is for PackML models only</source>
        <extracomment>%1: scenario syntax (&quot;command&quot;, &quot;expect state&quot;)</extracomment>
        <translation>&apos;%1&apos; solo es para modelos PackML</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is for GEMMA models only</source>
        <extracomment>%1: scenario syntax (&quot;expect step&quot;, &quot;set complete&quot;)</extracomment>
        <translation>&apos;%1&apos; solo es para modelos GEMMA</translation>
    </message>
    <message>
        <source>a %1 in scan %2 right after the one of line %3 is not seen: the request must be FALSE for one scan in between</source>
        <extracomment>%1: &quot;command&quot; or &quot;mode&quot; (scenario syntax); %2: a scan number; %3: a line number</extracomment>
        <translation>un %1 en el ciclo %2, justo después del de la línea %3, no se detecta: la petición debe estar en FALSE durante un ciclo entre ambos</translation>
    </message>
    <message>
        <source>%1 is a sensor of the machine&apos;s %2: the machine sets it; set it by hand in open loop only</source>
        <extracomment>%1: a variable; %2: the name of a component of the virtual machine (&quot;Clamp&quot;)</extracomment>
        <translation>%1 es un sensor del componente %2 de la máquina: la máquina lo fija; fíjelo a mano solo en lazo abierto</translation>
    </message>
    <message>
        <source>expected a sensor or component name after &apos;fault&apos;, found %1</source>
        <extracomment>&apos;fault&apos; is scenario syntax</extracomment>
        <translation>se esperaba un nombre de sensor o de componente después de &apos;fault&apos;, se encontró %1</translation>
    </message>
    <message>
        <source>expected stuck, flicker, jam or clear after the name, found %1</source>
        <extracomment>stuck, flicker, jam and clear are scenario syntax</extracomment>
        <translation>se esperaba stuck, flicker, jam o clear después del nombre, se encontró %1</translation>
    </message>
    <message>
        <source>a fault needs the virtual machine: run the scenario in closed loop, on a model with a machine</source>
        <translation>un fallo necesita la máquina virtual: ejecute el escenario en lazo cerrado, en un modelo con máquina</translation>
    </message>
    <message>
        <source>%1 is an operator input of the machine&apos;s %2: the user drives it with set; a fault applies to the machine&apos;s sensors</source>
        <extracomment>%1: a variable; %2: the name of a component of the virtual machine (&quot;Start&quot;); &apos;set&apos; is scenario syntax</extracomment>
        <translation>%1 es una entrada de operador de %2 de la máquina: el usuario la maneja con set; un fallo se aplica a los sensores de la máquina</translation>
    </message>
    <message>
        <source>%1 is no sensor of the machine: a fault applies to the inputs a component writes</source>
        <translation>%1 no es un sensor de la máquina: un fallo se aplica a las entradas que escribe un componente</translation>
    </message>
    <message>
        <source>no component &apos;%1&apos; in the machine</source>
        <translation>no hay ningún componente &apos;%1&apos; en la máquina</translation>
    </message>
    <message>
        <source>%1 is a %2: only cylinders and conveyors jam</source>
        <extracomment>%1: a component of the virtual machine; %2: its kind as the file spells it (&quot;lamp&quot;, &quot;push-button&quot;)</extracomment>
        <translation>%1 es de tipo %2: solo los cilindros y los transportadores se atascan</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is neither a sensor nor a component of the machine</source>
        <translation>&apos;%1&apos; no es ni un sensor ni un componente de la máquina</translation>
    </message>
</context>
<context>
    <name>SpecificationExport</name>
    <message>
        <source>%1 specification</source>
        <extracomment>the specification&apos;s title and the file name it is saved under; %1 is the model&apos;s name</extracomment>
        <translation>Especificación %1</translation>
    </message>
    <message>
        <source>GEMMA chart</source>
        <translation>Diagrama GEMMA</translation>
    </message>
    <message>
        <source>States</source>
        <translation>Estados</translation>
    </message>
    <message>
        <source>Transitions</source>
        <translation>Transiciones</translation>
    </message>
    <message>
        <source>Variables</source>
        <translation>Variables</translation>
    </message>
    <message>
        <source>Nested GRAFCETs</source>
        <translation>GRAFCET anidados</translation>
    </message>
    <message>
        <source>Generated code</source>
        <translation>Código generado</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Especificación</translation>
    </message>
    <message>
        <source>GEMMA-GRAFCET specification</source>
        <translation>Especificación GEMMA-GRAFCET</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errores</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n advertencia</numerusform>
            <numerusform>%n advertencias</numerusform>
        </translation>
    </message>
    <message>
        <source>File</source>
        <translation>Archivo</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>aún sin guardar</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Fecha</translation>
    </message>
    <message>
        <source>Initial state</source>
        <translation>Estado inicial</translation>
    </message>
    <message>
        <source>PLC task cycle</source>
        <translation>Ciclo de la tarea del PLC</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Code dialect</source>
        <translation>Dialecto del código</translation>
    </message>
    <message>
        <source>Nested GRAFCET evolution</source>
        <translation>Evolución de los GRAFCET anidados</translation>
    </message>
    <message>
        <source>Until stable, in one call of its function block</source>
        <translation>Hasta la estabilidad, en una llamada de su bloque de función</translation>
    </message>
    <message>
        <source>One evolution per PLC scan</source>
        <translation>Una evolución por ciclo del PLC</translation>
    </message>
    <message>
        <source>Checks</source>
        <translation>Comprobaciones</translation>
    </message>
    <message>
        <source>No problems found</source>
        <translation>No se ha encontrado ningún problema</translation>
    </message>
    <message>
        <source>Written by</source>
        <translation>Escrito con</translation>
    </message>
    <message>
        <source>GG Studio %1</source>
        <translation>GG Studio %1</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>Contenido</translation>
    </message>
    <message>
        <source>GEMMA chart, continued</source>
        <translation>Diagrama GEMMA, continuación</translation>
    </message>
    <message>
        <source>States, transitions and variables</source>
        <translation>Estados, transiciones y variables</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
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
        <translation>Comentario</translation>
    </message>
    <message>
        <source>%1, initial</source>
        <translation>%1, inicial</translation>
    </message>
    <message numerus="yes">
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n etapa</numerusform>
            <numerusform>%n etapas</numerusform>
        </translation>
    </message>
    <message>
        <source>The visible states of the GEMMA chart, in state order. A macro-step or an enclosing step runs its nested GRAFCET while it is active.</source>
        <translation>Los estados visibles del diagrama GEMMA, en el orden de los estados. Una macroetapa o una etapa encapsulante ejecuta su GRAFCET anidado mientras está activa.</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transición</translation>
    </message>
    <message>
        <source>Priority</source>
        <translation>Prioridad</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Condición</translation>
    </message>
    <message>
        <source>Tokens</source>
        <translation>Memorias</translation>
    </message>
    <message>
        <source>%1, negated</source>
        <translation>%1, negada</translation>
    </message>
    <message>
        <source>The transitions that take part: visible, between visible states. A state evaluates its transitions by priority, 1 first; a negated transition fires when its condition is FALSE.</source>
        <translation>Las transiciones que intervienen: visibles, entre estados visibles. Un estado evalúa sus transiciones por prioridad, la 1 primero; una transición negada se franquea cuando su condición es FALSE.</translation>
    </message>
    <message>
        <source>No transition takes part.</source>
        <translation>Ninguna transición interviene.</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Clase</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Valor inicial</translation>
    </message>
    <message>
        <source>The declared variables, in declaration order. Inputs are read from the machine, outputs written by the actions of the nested GRAFCETs, internal variables are the program&apos;s memory. A variable without a default starts at its type&apos;s (FALSE, 0).</source>
        <translation>Las variables declaradas, en el orden de su declaración. Las entradas se leen de la máquina, las salidas las escriben las acciones de los GRAFCET anidados, las variables internas son la memoria del programa. Una variable sin valor inicial empieza con el de su tipo (FALSE, 0).</translation>
    </message>
    <message>
        <source>No variables are declared.</source>
        <translation>No hay variables declaradas.</translation>
    </message>
    <message numerus="yes">
        <source>%n transition(s)</source>
        <translation>
            <numerusform>%n transición</numerusform>
            <numerusform>%n transiciones</numerusform>
        </translation>
    </message>
    <message>
        <source>function block %1</source>
        <translation>bloque de función %1</translation>
    </message>
    <message>
        <source>This GRAFCET has no steps yet.</source>
        <translation>Este GRAFCET aún no tiene etapas.</translation>
    </message>
    <message>
        <source>Nested GRAFCET of %1, continued</source>
        <translation>GRAFCET anidado de %1, continuación</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Etapa</translation>
    </message>
    <message>
        <source>Steps of %1</source>
        <translation>Etapas de %1</translation>
    </message>
    <message>
        <source>GG Studio generates the PLC program as IEC 61131-3 Structured Text by the Hierarchical Design Pattern: the program %1 holds the active GEMMA state and evaluates its transitions by priority, and each visible macro-step or enclosing step is a function block that %1 calls while that state is active. This outline gives the program organisation units and their interfaces; File &gt; Export Structured Text and Export PLCopen XML write the code itself.</source>
        <translation>GG Studio genera el programa del PLC como Structured Text IEC 61131-3 según el Hierarchical Design Pattern: el programa %1 guarda el estado GEMMA activo y evalúa sus transiciones por prioridad, y cada macroetapa o etapa encapsulante visible es un bloque de función que %1 llama mientras ese estado está activo. Este esquema da las unidades de organización de programa y sus interfaces; Archivo &gt; Exportar a texto estructurado (ST) y Exportar a PLCopen XML escriben el código en sí.</translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s): the generated code marks each one with a comment.</source>
        <translation>
            <numerusform>El modelo tiene %n error: el código generado lo marca con un comentario.</numerusform>
            <numerusform>El modelo tiene %n errores: el código generado marca cada uno con un comentario.</numerusform>
        </translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configuración</translation>
    </message>
    <message>
        <source>Resource</source>
        <translation>Recurso</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Tarea</translation>
    </message>
    <message>
        <source>%1: cyclic, every %2, priority %3</source>
        <translation>%1: cíclica, cada %2, prioridad %3</translation>
    </message>
    <message>
        <source>Program instance</source>
        <translation>Instancia del programa</translation>
    </message>
    <message>
        <source>Global variable list</source>
        <translation>Lista de variables globales</translation>
    </message>
    <message>
        <source>The GEMMA layer: it holds the active state in State, evaluates that state&apos;s transitions by priority and calls the function block of a state with nested behaviour while that state is active.</source>
        <translation>La capa GEMMA: guarda el estado activo en State, evalúa las transiciones de ese estado por prioridad y llama al bloque de función de un estado con comportamiento anidado mientras ese estado está activo.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 (page %2). %3 calls it through its instance %4 while %4 is active.</source>
        <translation>El GRAFCET anidado de %1 (página %2). %3 lo llama mediante su instancia %4 mientras %4 está activa.</translation>
    </message>
    <message>
        <source>The nested behaviour of %1, not written yet: until it is, the function block completes at once. %2 calls it through its instance %3.</source>
        <translation>El comportamiento anidado de %1, aún sin escribir: mientras tanto, el bloque de función termina enseguida. %2 lo llama mediante su instancia %3.</translation>
    </message>
    <message>
        <source>Declaration</source>
        <translation>Declaración</translation>
    </message>
    <message>
        <source>Initial value</source>
        <translation>Valor inicial</translation>
    </message>
    <message>
        <source>Global variables it reads (VAR_EXTERNAL): %1.</source>
        <translation>Variables globales que lee (VAR_EXTERNAL): %1.</translation>
    </message>
    <message>
        <source>Its own variables (VAR): %1.</source>
        <translation>Sus propias variables (VAR): %1.</translation>
    </message>
    <message>
        <source>Global variables</source>
        <translation>Variables globales</translation>
    </message>
    <message>
        <source>in the VAR_GLOBAL of the configuration %1</source>
        <translation>en el VAR_GLOBAL de la configuración %1</translation>
    </message>
    <message>
        <source>in the global variable list %1</source>
        <translation>en la lista de variables globales %1</translation>
    </message>
    <message>
        <source>The declared variables (page %1) are the program&apos;s global variables, %2.</source>
        <translation>Las variables declaradas (página %1) son las variables globales del programa, %2.</translation>
    </message>
    <message>
        <source>The generator adds these:</source>
        <translation>El generador añade estas:</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Página %1 de %2</translation>
    </message>
    <message>
        <source>PackML chart</source>
        <translation>Diagrama PackML</translation>
    </message>
    <message>
        <source>Commands, modes and variables</source>
        <translation>Comandos, modos y variables</translation>
    </message>
    <message>
        <source>Unit mode %1</source>
        <translation>Modo de unidad %1</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Comandos</translation>
    </message>
    <message>
        <source>Unit modes</source>
        <translation>Modos de unidad</translation>
    </message>
    <message>
        <source>PackML, 2022 edition</source>
        <translation>PackML, edición 2022</translation>
    </message>
    <message>
        <source>PackML, 2015 edition</source>
        <translation>PackML, edición 2015</translation>
    </message>
    <message>
        <source>Hold accepted in Suspended</source>
        <translation>Hold aceptado en Suspended</translation>
    </message>
    <message>
        <source>Complete accepted in Suspended and Held</source>
        <translation>Complete aceptado en Suspended y Held</translation>
    </message>
    <message>
        <source>%1; options: %2</source>
        <translation>%1; opciones: %2</translation>
    </message>
    <message>
        <source>Template</source>
        <translation>Plantilla</translation>
    </message>
    <message>
        <source>Initial unit mode</source>
        <translation>Modo de unidad inicial</translation>
    </message>
    <message>
        <source>PackML specification</source>
        <translation>Especificación PackML</translation>
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
        <translation>Los comandos de la edición, con la condición cuyo flanco ascendente emite cada uno (además de CntrlCmd). Un comando que un estado no acepta se ignora en él.</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <source>Request condition</source>
        <translation>Condición de solicitud</translation>
    </message>
    <message>
        <source>Disabled states</source>
        <translation>Estados desactivados</translation>
    </message>
    <message>
        <source>Mode change allowed in</source>
        <translation>Cambio de modo permitido en</translation>
    </message>
    <message>
        <source>The unit modes, in number order. A mode skips its disabled states; the unit changes to a mode when its request condition rises while the current mode allows a change in the current state.</source>
        <translation>Los modos de unidad, por número. Un modo salta sus estados desactivados; la unidad pasa a un modo cuando su condición de solicitud sube mientras el modo actual permite un cambio en el estado actual.</translation>
    </message>
    <message>
        <source>Nested GRAFCET</source>
        <translation>GRAFCET anidado</translation>
    </message>
    <message>
        <source>Nested GRAFCETs in %1</source>
        <translation>GRAFCET anidados en %1</translation>
    </message>
    <message>
        <source>None: the mode disables this state</source>
        <translation>Ninguno: el modo desactiva este estado</translation>
    </message>
    <message>
        <source>Own: %1</source>
        <translation>Propio: %1</translation>
    </message>
    <message>
        <source>Same as mode %1: %2</source>
        <translation>El mismo que el modo %1: %2</translation>
    </message>
    <message>
        <source>Same as mode %1, which does not exist</source>
        <translation>El mismo que el modo %1, que no existe</translation>
    </message>
    <message>
        <source>None: the state completes at once</source>
        <translation>Ninguno: el estado se completa enseguida</translation>
    </message>
    <message>
        <source>None: Execute waits for a command</source>
        <translation>Ninguno: Execute espera un comando</translation>
    </message>
    <message>
        <source>Nested GRAFCET %1, continued</source>
        <translation>GRAFCET anidado %1, continuación</translation>
    </message>
    <message>
        <source>GG Studio generates the PLC program as IEC 61131-3 Structured Text by the PackML design pattern: the program %1 is the state and mode manager, with the PackTags interface; it calls, in each acting state and Execute, the function block instance of the current unit mode and state, whose State Complete ends that state. This outline gives the program organisation units and their interfaces; File &gt; Export Structured Text and Export PLCopen XML write the code itself.</source>
        <translation>GG Studio genera el programa del PLC en texto estructurado IEC 61131-3 según el patrón de diseño PackML: el programa %1 es el gestor de estados y modos, con la interfaz PackTags; llama, en cada estado activo y en Execute, a la instancia de bloque de función del modo de unidad y el estado actuales, cuyo State Complete termina ese estado. Este esquema da las unidades de organización de programa y sus interfaces; Archivo &gt; Exportar texto estructurado y Exportar PLCopen XML escriben el código en sí.</translation>
    </message>
    <message>
        <source>The PackML state and mode manager: it latches the commands and mode requests, holds the current state and unit mode in StateCurrent and UnitModeCurrent, evaluates the current state&apos;s transitions in the current mode and calls the function block instance of that mode and state.</source>
        <translation>El gestor de estados y modos PackML: memoriza los comandos y las solicitudes de modo, guarda el estado y el modo de unidad actuales en StateCurrent y UnitModeCurrent, evalúa las transiciones del estado actual en el modo actual y llama a la instancia de bloque de función de ese modo y ese estado.</translation>
    </message>
    <message>
        <source>The nested GRAFCET %1 (page %2). %3 calls it while the unit is in %4 in a mode that runs it; its Complete is that state&apos;s State Complete.</source>
        <translation>El GRAFCET anidado %1 (página %2). %3 lo llama mientras la unidad está en %4 en un modo que lo ejecuta; su Complete es el State Complete de ese estado.</translation>
    </message>
    <message>
        <source>The function block of %1 in the modes without a GRAFCET there: %2</source>
        <translation>El bloque de función de %1 en los modos sin GRAFCET allí: %2</translation>
    </message>
    <message>
        <source>it completes at once.</source>
        <translation>se completa enseguida.</translation>
    </message>
    <message>
        <source>it does nothing, Execute waits for a command.</source>
        <translation>no hace nada, Execute espera un comando.</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>Component</source>
        <translation>Componente</translation>
    </message>
    <message>
        <source>Wiring</source>
        <translation>Cableado</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Ajustes</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>ilimitado</translation>
    </message>
    <message>
        <source>Feeds %1</source>
        <translation>Alimenta %1</translation>
    </message>
    <message>
        <source>The virtual machine the simulation runs the program against, in closed loop: after each scan the components move one cycle time from the outputs wired to them and set the sensors the next scan reads; operator inputs stay the user&apos;s. Times are in milliseconds, counted in whole cycles.</source>
        <translation>La máquina virtual contra la que la simulación ejecuta el programa, en lazo cerrado: tras cada ciclo los componentes se mueven un tiempo de ciclo según las salidas cableadas a ellos y fijan los sensores que lee el ciclo siguiente; las entradas del operador siguen siendo del usuario. Los tiempos están en milisegundos, contados en ciclos enteros.</translation>
    </message>
    <message>
        <source>The machine at rest</source>
        <translation>La máquina en reposo</translation>
    </message>
</context>
<context>
    <name>StateNames</name>
    <message>
        <source>Stop in initial state</source>
        <translation>Parada en el estado inicial</translation>
    </message>
    <message>
        <source>Stop requested at end of cycle</source>
        <translation>Parada solicitada a fin de ciclo</translation>
    </message>
    <message>
        <source>Stop requested in a given state</source>
        <translation>Parada solicitada en un estado determinado</translation>
    </message>
    <message>
        <source>Stop obtained</source>
        <translation>Parada obtenida</translation>
    </message>
    <message>
        <source>Preparation for restart after failure</source>
        <translation>Preparación para la puesta en marcha tras un fallo</translation>
    </message>
    <message>
        <source>Operative part reset to initial state</source>
        <translation>Puesta de la parte operativa en el estado inicial</translation>
    </message>
    <message>
        <source>Operative part set to a given state</source>
        <translation>Puesta de la parte operativa en un estado determinado</translation>
    </message>
    <message>
        <source>Normal production</source>
        <translation>Producción normal</translation>
    </message>
    <message>
        <source>Preparation run</source>
        <translation>Marcha de preparación</translation>
    </message>
    <message>
        <source>Closing run</source>
        <translation>Marcha de cierre</translation>
    </message>
    <message>
        <source>Verification run out of order</source>
        <translation>Marcha de verificación en desorden</translation>
    </message>
    <message>
        <source>Verification run in order</source>
        <translation>Marcha de verificación en orden</translation>
    </message>
    <message>
        <source>Test run</source>
        <translation>Marcha de test</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Parada de emergencia</translation>
    </message>
    <message>
        <source>Diagnosis and/or failure handling</source>
        <translation>Diagnóstico y/o tratamiento de fallos</translation>
    </message>
    <message>
        <source>Production despite failure</source>
        <translation>Producción a pesar de los fallos</translation>
    </message>
    <message>
        <source>Stop procedures</source>
        <translation>Procedimientos de parada</translation>
    </message>
    <message>
        <source>Operation procedures</source>
        <translation>Procedimientos de funcionamiento</translation>
    </message>
    <message>
        <source>Failure procedures</source>
        <translation>Procedimientos de fallo</translation>
    </message>
</context>
<context>
    <name>ValueProblemText</name>
    <message>
        <source>&apos;%1&apos; is not an %2 literal: write a whole number such as 42</source>
        <extracomment>%1: the value as written; %2: INT</extracomment>
        <translation>&apos;%1&apos; no es un literal %2: escriba un número entero, por ejemplo 42</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a %2 literal: write a whole number such as 42</source>
        <extracomment>%1: the value as written; %2: an integer type other than INT (SINT, UDINT...)</extracomment>
        <translation>&apos;%1&apos; no es un literal %2: escriba un número entero, por ejemplo 42</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has leading or trailing spaces</source>
        <translation>&apos;%1&apos; tiene espacios al principio o al final</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a BOOL literal (TRUE or FALSE)</source>
        <translation>&apos;%1&apos; no es un literal BOOL (TRUE o FALSE)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a %2 literal: write a decimal number such as 1.5 or 2.0E3</source>
        <extracomment>%1: the value as written; %2: REAL or LREAL</extracomment>
        <translation>&apos;%1&apos; no es un literal %2: escriba un número decimal, por ejemplo 1.5 o 2.0E3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range for %2 (%3..%4)</source>
        <extracomment>%1: the value as written; %2: its IEC type; %3..%4: the type&apos;s range</extracomment>
        <translation>&apos;%1&apos; está fuera del rango de %2 (%3..%4)</translation>
    </message>
</context>
<context>
    <name>editor::Autosave</name>
    <message>
        <source>Cannot create the folder %1 for recovery copies</source>
        <translation>No se puede crear la carpeta %1 para las copias de recuperación</translation>
    </message>
    <message>
        <source>Cannot write the recovery copy: %1</source>
        <translation>No se puede escribir la copia de recuperación: %1</translation>
    </message>
    <message>
        <source>Cannot lock the recovery copy %1</source>
        <translation>No se puede bloquear la copia de recuperación %1</translation>
    </message>
    <message>
        <source>Another GG Studio is using the recovery copy %1.</source>
        <translation>Otra instancia de GG Studio está usando la copia de recuperación %1.</translation>
    </message>
</context>
<context>
    <name>editor::BranchDrag</name>
    <message>
        <source>Step %1 is on no branch of a divergence: there is no branch to move</source>
        <translation>La etapa %1 no está en ninguna rama de una divergencia: no hay rama que mover</translation>
    </message>
    <message>
        <source>Move the branch of step %1 left in %2</source>
        <translation>Mover la rama de la etapa %1 a la izquierda en %2</translation>
    </message>
    <message>
        <source>Move the branch of step %1 right in %2</source>
        <translation>Mover la rama de la etapa %1 a la derecha en %2</translation>
    </message>
</context>
<context>
    <name>editor::ChartContextMenu</name>
    <message>
        <source>&amp;Show %1</source>
        <translation>&amp;Mostrar %1</translation>
    </message>
    <message>
        <source>&amp;Hide %1</source>
        <translation>&amp;Ocultar %1</translation>
    </message>
    <message>
        <source>Step &amp;Type</source>
        <translation>&amp;Tipo de etapa</translation>
    </message>
    <message>
        <source>Make &amp;Initial Step</source>
        <translation>Convertir en etapa &amp;inicial</translation>
    </message>
    <message>
        <source>Edit &amp;Comment…</source>
        <translation>Editar el &amp;comentario…</translation>
    </message>
    <message>
        <source>Edit &amp;Condition…</source>
        <translation>Editar la &amp;condición…</translation>
    </message>
    <message>
        <source>&amp;Negated</source>
        <translation>&amp;Negada</translation>
    </message>
    <message>
        <source>Flips whether this transition waits for Complete of its source&apos;s nested behaviour</source>
        <translation>Invierte si esta transición espera Complete del comportamiento anidado de su etapa de origen</translation>
    </message>
    <message>
        <source>Priority &amp;Up</source>
        <translation>&amp;Subir la prioridad</translation>
    </message>
    <message>
        <source>Priority &amp;Down</source>
        <translation>&amp;Bajar la prioridad</translation>
    </message>
    <message numerus="yes">
        <source>Hide the %n Selected Elements</source>
        <translation>
            <numerusform>Ocultar el elemento seleccionado</numerusform>
            <numerusform>Ocultar los %n elementos seleccionados</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show the %n Selected Elements</source>
        <translation>
            <numerusform>Mostrar el elemento seleccionado</numerusform>
            <numerusform>Mostrar los %n elementos seleccionados</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Open Nested GRAFCET</source>
        <translation>&amp;Abrir el GRAFCET anidado</translation>
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
        <translation>Condiciones</translation>
    </message>
</context>
<context>
    <name>editor::ConnectTransitionDialog</name>
    <message>
        <source>Connect T%1 of %2</source>
        <extracomment>%1 the transition&apos;s number, %2 the GEMMA step whose GRAFCET it is in</extracomment>
        <translation>Conectar T%1 de %2</translation>
    </message>
    <message>
        <source>Upstream steps (it leaves them)</source>
        <translation>Etapas anteriores (las desactiva)</translation>
    </message>
    <message>
        <source>Downstream steps (it activates them)</source>
        <translation>Etapas siguientes (las activa)</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Etapa %1</translation>
    </message>
    <message>
        <source>Tick an upstream step: a transition leaves at least one step.</source>
        <translation>Marque una etapa anterior: una transición deja al menos una etapa.</translation>
    </message>
    <message>
        <source>Tick a downstream step: a transition activates at least one step. To end a branch on a step with no transition after it, use Add Branch Ending on a Step on the step.</source>
        <translation>Marque una etapa siguiente: una transición activa al menos una etapa. Para terminar una rama en una etapa sin transición después, use «Añadir rama que termina en una etapa» en la etapa.</translation>
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
        <translation>Sin título</translation>
    </message>
    <message>
        <source>Stop the simulation to edit the model</source>
        <translation>Detenga la simulación para editar el modelo</translation>
    </message>
</context>
<context>
    <name>editor::ExportActions</name>
    <message>
        <source>Export &amp;PLCopen XML…</source>
        <translation>Exportar a &amp;PLCopen XML…</translation>
    </message>
    <message>
        <source>Write the PLC program as PLCopen XML, to import into a PLC programming tool</source>
        <translation>Escribir el programa del PLC en PLCopen XML, para importarlo en una herramienta de programación de PLC</translation>
    </message>
    <message>
        <source>Export &amp;Structured Text…</source>
        <translation>Exportar a &amp;texto estructurado (ST)…</translation>
    </message>
    <message>
        <source>Write the PLC program as IEC 61131-3 Structured Text files</source>
        <translation>Escribir el programa del PLC en archivos de texto estructurado (ST) IEC 61131-3</translation>
    </message>
    <message>
        <source>Export &amp;GG-Generator JSON…</source>
        <translation>Exportar a &amp;JSON de GG-Generator…</translation>
    </message>
    <message>
        <source>Save the model in the format of the GG-Generator web tool</source>
        <translation>Guardar el modelo en el formato de la herramienta web GG-Generator</translation>
    </message>
    <message>
        <source>Export &amp;Chart…</source>
        <translation>Exportar el &amp;diagrama…</translation>
    </message>
    <message>
        <source>Save the chart as an SVG, PNG or PDF picture</source>
        <translation>Guardar el diagrama como imagen SVG, PNG o PDF</translation>
    </message>
    <message>
        <source>&amp;Print…</source>
        <translation>&amp;Imprimir…</translation>
    </message>
    <message>
        <source>Print the chart</source>
        <translation>Imprimir el diagrama</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… y %n más</numerusform>
            <numerusform>… y %n más</numerusform>
        </translation>
    </message>
    <message>
        <source>Export a Model with Errors</source>
        <translation>Exportar un modelo con errores</translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s). The generated code marks each one with a comment, but it may not compile or may not behave as intended.</source>
        <translation>
            <numerusform>El modelo tiene %n error. El código generado lo señala con un comentario, pero puede que no compile o que no se comporte como se espera.</numerusform>
            <numerusform>El modelo tiene %n errores. El código generado señala cada uno con un comentario, pero puede que no compile o que no se comporte como se espera.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Export Anyway</source>
        <translation>&amp;Exportar de todos modos</translation>
    </message>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Exportar a PLCopen XML</translation>
    </message>
    <message>
        <source>PLCopen XML (*.xml)</source>
        <translation>PLCopen XML (*.xml)</translation>
    </message>
    <message>
        <source>Export Structured Text</source>
        <translation>Exportar a texto estructurado (ST)</translation>
    </message>
    <message>
        <source>Structured Text (*.st)</source>
        <translation>Texto estructurado (*.st)</translation>
    </message>
    <message>
        <source>Export Structured Text to a Folder</source>
        <translation>Exportar a texto estructurado (ST) en una carpeta</translation>
    </message>
    <message>
        <source>Export GG-Generator JSON</source>
        <translation>Exportar a JSON de GG-Generator</translation>
    </message>
    <message>
        <source>GG-Generator JSON (*.json)</source>
        <translation>JSON de GG-Generator (*.json)</translation>
    </message>
    <message>
        <source>SVG picture (*.svg)</source>
        <translation>Imagen SVG (*.svg)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Imagen PNG (*.png)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Documento PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export Chart</source>
        <translation>Exportar el diagrama</translation>
    </message>
    <message>
        <source>Print Chart</source>
        <translation>Imprimir el diagrama</translation>
    </message>
    <message>
        <source>The printer could not be started.</source>
        <translation>No se ha podido iniciar la impresora.</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>Se ha exportado a %1</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Error al exportar</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>No se ha podido escribir %1.</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>sin título</translation>
    </message>
    <message>
        <source>The nested GRAFCETs of %1: GG-Generator has no place for nested behaviour.</source>
        <translation>Los GRAFCET anidados de %1: GG-Generator no tiene lugar para el comportamiento anidado.</translation>
    </message>
    <message>
        <source>The variable kinds (output, internal): GG-Generator reads every variable as an input.</source>
        <translation>Los tipos de variable (salida, interna): GG-Generator lee todas las variables como entradas.</translation>
    </message>
    <message>
        <source>The until-stable evolution rule: GG-Generator knows one evolution per scan only.</source>
        <translation>La regla de evolución «hasta la estabilidad»: GG-Generator solo conoce una evolución por ciclo.</translation>
    </message>
    <message>
        <source>Export to GG-Generator</source>
        <translation>Exportar a GG-Generator</translation>
    </message>
    <message>
        <source>The GG-Generator file will leave out part of this model. Your model and its own file keep everything.</source>
        <translation>El archivo de GG-Generator dejará fuera parte de este modelo. Su modelo y su propio archivo lo conservan todo.</translation>
    </message>
    <message>
        <source>%1, nested GRAFCET of %2</source>
        <translation>%1, GRAFCET anidado de %2</translation>
    </message>
    <message>
        <source>Export Speci&amp;fication…</source>
        <translation>Exportar la especi&amp;ficación…</translation>
    </message>
    <message>
        <source>Write the whole model as one PDF document: the chart, the states, the variables, every nested GRAFCET and the outline of the generated code</source>
        <translation>Escribir todo el modelo como un único documento PDF: el diagrama, los estados, las variables, cada GRAFCET anidado y el esquema del código generado</translation>
    </message>
    <message>
        <source>Export Specification</source>
        <translation>Exportar la especificación</translation>
    </message>
    <message>
        <source>The verification properties: GG-Generator has no place for them.</source>
        <translation>Las propiedades de verificación: GG-Generator no tiene lugar para ellas.</translation>
    </message>
    <message>
        <source>Writing the specification…</source>
        <translation>Escribiendo la especificación…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Export cancelled: %1 left unchanged</source>
        <translation>Exportación cancelada: %1 no se ha modificado</translation>
    </message>
</context>
<context>
    <name>editor::ExportOptionsDialog</name>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Exportar a PLCopen XML</translation>
    </message>
    <message>
        <source>Export Structured Text</source>
        <translation>Exportar a texto estructurado (ST)</translation>
    </message>
    <message>
        <source>One file per POU, in a &amp;folder</source>
        <translation>Un archivo por POU, en una &amp;carpeta</translation>
    </message>
    <message>
        <source>One &amp;IEC 61131-3 file with every POU</source>
        <translation>Un único archivo &amp;IEC 61131-3 con todas las POU</translation>
    </message>
    <message>
        <source>Files:</source>
        <translation>Archivos:</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialecto:</translation>
    </message>
    <message>
        <source>IEC writes PLCopen TC6 XML 2.01 with the globals in the configuration. CODESYS writes what CODESYS V3.5 imports, with a GVL.</source>
        <translation>IEC escribe PLCopen TC6 XML 2.01 con las variables globales en la configuración. CODESYS escribe lo que importa CODESYS V3.5, con una GVL.</translation>
    </message>
    <message>
        <source>The single file is always IEC 61131-3: CODESYS code names a GVL that IEC compilers do not know.</source>
        <translation>El archivo único es siempre IEC 61131-3: el código CODESYS hace referencia a una GVL que los compiladores IEC no conocen.</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportar…</translation>
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
        <translation>Insertar etapa &amp;después</translation>
    </message>
    <message>
        <source>Insert Step &amp;Before</source>
        <translation>Insertar etapa &amp;antes</translation>
    </message>
    <message>
        <source>Add &amp;Selection Branch</source>
        <translation>Añadir rama de &amp;selección</translation>
    </message>
    <message>
        <source>Add &amp;Parallel Branch</source>
        <translation>Añadir rama &amp;paralela</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Quitar</translation>
    </message>
    <message>
        <source>Remove Bra&amp;nch</source>
        <translation>Quitar ra&amp;ma</translation>
    </message>
    <message>
        <source>Ren&amp;umber Steps and Transitions</source>
        <translation>Ren&amp;umerar etapas y transiciones</translation>
    </message>
    <message>
        <source>&amp;Connect Directly…</source>
        <translation>&amp;Conectar directamente…</translation>
    </message>
    <message>
        <source>&amp;Copy Steps</source>
        <translation>&amp;Copiar etapas</translation>
    </message>
    <message>
        <source>&amp;Paste Steps</source>
        <translation>&amp;Pegar etapas</translation>
    </message>
    <message>
        <source>Create the &amp;Usual Shape</source>
        <translation>Crear la forma &amp;habitual</translation>
    </message>
    <message>
        <source>Initial step 1, then step 2, then step 3, which sets Complete</source>
        <translation>Etapa inicial 1, luego etapa 2, luego etapa 3, que activa Complete</translation>
    </message>
    <message>
        <source>%1 has no GRAFCET yet.&lt;br&gt;&lt;a href=&quot;create&quot;&gt;Create the usual shape&lt;/a&gt;: initial step 1, step 2, and step 3, which sets Complete.</source>
        <extracomment>%1 the GEMMA step; the link creates its GRAFCET</extracomment>
        <translation>%1 aún no tiene GRAFCET.&lt;br&gt;&lt;a href=&quot;create&quot;&gt;Crear la forma habitual&lt;/a&gt;: etapa inicial 1, etapa 2 y etapa 3, que activa Complete.</translation>
    </message>
    <message>
        <source>Add Loop or &amp;Jump To</source>
        <translation>Añadir bucle o &amp;salto a</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Etapa %1</translation>
    </message>
    <message>
        <source>Add step %1 to %2</source>
        <translation>Añadir la etapa %1 a %2</translation>
    </message>
    <message>
        <source>Add selection branch to %1</source>
        <translation>Añadir rama de selección a %1</translation>
    </message>
    <message>
        <source>Add parallel branch to %1</source>
        <translation>Añadir rama paralela a %1</translation>
    </message>
    <message>
        <source>Add jump from step %1 to step %2 in %3</source>
        <extracomment>%1 and %2 step numbers, %3 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Añadir salto de la etapa %1 a la etapa %2 en %3</translation>
    </message>
    <message>
        <source>Remove step %1 from %2</source>
        <translation>Quitar la etapa %1 de %2</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n steps from %1</source>
        <translation>
            <numerusform>Quitar %n etapa de %1</numerusform>
            <numerusform>Quitar %n etapas de %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Remove branch from %1</source>
        <translation>Quitar una rama de %1</translation>
    </message>
    <message>
        <source>Renumber %1</source>
        <translation>Renumerar %1</translation>
    </message>
    <message>
        <source>Connect %1 T%2</source>
        <extracomment>%1 the GEMMA step, %2 the transition&apos;s number</extracomment>
        <translation>Conectar %1 T%2</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n steps into %1</source>
        <translation>
            <numerusform>Pegar %n etapa en %1</numerusform>
            <numerusform>Pegar %n etapas en %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Create GRAFCET of %1</source>
        <translation>Crear el GRAFCET de %1</translation>
    </message>
    <message>
        <source>Add Branch &amp;Ending on a Step</source>
        <translation>Añadir rama que &amp;termina en una etapa</translation>
    </message>
    <message>
        <source>A new branch from this step to a new step with no transition after it (an exit step)</source>
        <translation>Una nueva rama de esta etapa a una nueva etapa sin transición después (una etapa de salida)</translation>
    </message>
    <message>
        <source>Move Branch &amp;Left</source>
        <translation>Mover la rama a la &amp;izquierda</translation>
    </message>
    <message>
        <source>Swap the branch holding this step with the one at its left</source>
        <translation>Intercambia la rama que contiene esta etapa con la de su izquierda</translation>
    </message>
    <message>
        <source>Move Branch Ri&amp;ght</source>
        <translation>Mover la rama a la &amp;derecha</translation>
    </message>
    <message>
        <source>Swap the branch holding this step with the one at its right</source>
        <translation>Intercambia la rama que contiene esta etapa con la de su derecha</translation>
    </message>
    <message>
        <source>Cu&amp;t Steps</source>
        <translation>Cor&amp;tar etapas</translation>
    </message>
    <message>
        <source>Add branch ending on a step at step %1 in %2</source>
        <extracomment>%1 the step the branch leaves, %2 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Añadir rama que termina en una etapa en la etapa %1 de %2</translation>
    </message>
    <message>
        <source>Move branch left in %1</source>
        <extracomment>%1 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Mover una rama a la izquierda en %1</translation>
    </message>
    <message>
        <source>Move branch right in %1</source>
        <translation>Mover una rama a la derecha en %1</translation>
    </message>
    <message>
        <source>Remove T%1 from %2</source>
        <translation>Quitar T%1 de %2</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n transitions from %1</source>
        <translation>
            <numerusform>Quitar %n transición de %1</numerusform>
            <numerusform>Quitar %n transiciones de %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remove %n elements from %1</source>
        <translation>
            <numerusform>Quitar %n elemento de %1</numerusform>
            <numerusform>Quitar %n elementos de %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Cut step %1 from %2</source>
        <translation>Cortar la etapa %1 de %2</translation>
    </message>
    <message numerus="yes">
        <source>Cut %n steps from %1</source>
        <translation>
            <numerusform>Cortar %n etapa de %1</numerusform>
            <numerusform>Cortar %n etapas de %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::GrafcetActionsModel</name>
    <message>
        <source>When</source>
        <translation>Cuándo</translation>
    </message>
    <message>
        <source>Qual.</source>
        <extracomment>short: the column is narrow; its tooltip says &quot;qualifier&quot; in full</extracomment>
        <translation>Cal.</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>IF / value</source>
        <extracomment>the condition after IF of an N action, or the value of a := action; short: the column is narrow</extracomment>
        <translation>IF / valor</translation>
    </message>
    <message>
        <source>While the step is active (N), or once when it is activated or deactivated (S, R, :=)</source>
        <translation>Mientras la etapa está activa (N), o una vez al activarse o desactivarse (S, R, :=)</translation>
    </message>
    <message>
        <source>Qualifier. N: the variable is TRUE while the step is active
S, R: set it TRUE or FALSE
:=: assign it the value</source>
        <translation>Calificador. N: la variable es TRUE mientras la etapa está activa
S, R: ponerla a TRUE o FALSE
:=: asignarle el valor</translation>
    </message>
    <message>
        <source>An output or internal variable, or Complete</source>
        <translation>Una variable de salida o interna, o Complete</translation>
    </message>
    <message>
        <source>N: only IF this condition holds (may be empty)
:=: the value assigned</source>
        <translation>N: solo SI se cumple esta condición (puede estar vacía)
:=: el valor asignado</translation>
    </message>
    <message>
        <source>While active</source>
        <translation>Mientras activa</translation>
    </message>
    <message>
        <source>On activation</source>
        <translation>Al activarse</translation>
    </message>
    <message>
        <source>On deactivation</source>
        <translation>Al desactivarse</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetSimulationMarks</name>
    <message>
        <source>%1 is active: its GRAFCET runs. Unstable: the last scan ended without a stable situation</source>
        <translation>%1 está activa: su GRAFCET evoluciona. Unstable: el último ciclo terminó sin una situación estable</translation>
    </message>
    <message>
        <source>%1 has just been entered: its GRAFCET starts from its initial steps in the next scan</source>
        <translation>%1 acaba de activarse: su GRAFCET empieza en sus etapas iniciales en el próximo ciclo</translation>
    </message>
    <message>
        <source>%1 is not active: its GRAFCET is shown greyed, as it was left</source>
        <translation>%1 no está activa: su GRAFCET se muestra en gris, tal como quedó</translation>
    </message>
    <message numerus="yes">
        <source>%1 is active: its GRAFCET runs (step(s) %2)</source>
        <translation>
            <numerusform>%1 está activa: su GRAFCET evoluciona (etapa %2)</numerusform>
            <numerusform>%1 está activa: su GRAFCET evoluciona (etapas %2)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 has just been resumed: its GRAFCET goes on where it was paused in the next scan</source>
        <translation>%1 acaba de reanudarse: su GRAFCET continúa donde se pausó en el próximo ciclo</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetStepDock</name>
    <message>
        <source>Nested Step</source>
        <translation>Etapa anidada</translation>
    </message>
    <message>
        <source>Select a step in a nested GRAFCET&apos;s tab to see and edit its number, comment and actions.</source>
        <translation>Seleccione una etapa en la pestaña de un GRAFCET anidado para ver y editar su número, comentario y acciones.</translation>
    </message>
    <message>
        <source>&amp;Number:</source>
        <translation>&amp;Número:</translation>
    </message>
    <message>
        <source>Unique in this GRAFCET; its activity is X&lt;number&gt;. The transitions and the X&lt;number&gt; of the receptivities and actions follow a new number.</source>
        <translation>Único en este GRAFCET; su actividad es X&lt;número&gt;. Las transiciones y los X&lt;número&gt; de las receptividades y acciones siguen a un número nuevo.</translation>
    </message>
    <message>
        <source>&amp;Initial</source>
        <translation>&amp;Inicial</translation>
    </message>
    <message>
        <source>Active when the GEMMA state is entered (a GRAFCET needs at least one)</source>
        <translation>Activa al entrar en el estado GEMMA (un GRAFCET necesita al menos una)</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Comentario:</translation>
    </message>
    <message>
        <source>What the machine does in this step</source>
        <translation>Lo que hace la máquina en esta etapa</translation>
    </message>
    <message>
        <source>&amp;Actions:</source>
        <translation>&amp;Acciones:</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Añadir</translation>
    </message>
    <message>
        <source>Add an action after the current one</source>
        <translation>Añadir una acción después de la actual</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>Remove the current action</source>
        <translation>Quitar la acción actual</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Subir</translation>
    </message>
    <message>
        <source>Run the current action earlier</source>
        <translation>Ejecutar antes la acción actual</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Bajar</translation>
    </message>
    <message>
        <source>Run the current action later</source>
        <translation>Ejecutar después la acción actual</translation>
    </message>
    <message>
        <source>%1 step %2</source>
        <extracomment>A step of the nested GRAFCET of a GEMMA step: &quot;F1 step 3&quot;</extracomment>
        <translation>%1 etapa %2</translation>
    </message>
    <message>
        <source>In the nested GRAFCET of %1 %2</source>
        <translation>En el GRAFCET anidado de %1 %2</translation>
    </message>
    <message>
        <source>%1 already has a step %2: choose another number.</source>
        <translation>%1 ya tiene una etapa %2: elija otro número.</translation>
    </message>
    <message>
        <source>Step numbers start at 1: %1 is not a step number.</source>
        <translation>Los números de etapa empiezan en 1: %1 no es un número de etapa.</translation>
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
        <translation>El GRAFCET de %1 en el modo %2</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1</source>
        <translation>El GRAFCET anidado de %1</translation>
    </message>
    <message>
        <source>PackML Chart</source>
        <translation>Diagrama PackML</translation>
    </message>
    <message>
        <source>GEMMA Chart</source>
        <translation>Diagrama GEMMA</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetTransitionDock</name>
    <message>
        <source>Nested Transition</source>
        <translation>Transición anidada</translation>
    </message>
    <message>
        <source>Select a transition in a nested GRAFCET&apos;s tab to see and edit its receptivity.</source>
        <translation>Seleccione una transición en la pestaña de un GRAFCET anidado para ver y editar su receptividad.</translation>
    </message>
    <message>
        <source>From steps:</source>
        <translation>Desde las etapas:</translation>
    </message>
    <message>
        <source>To steps:</source>
        <translation>Hacia las etapas:</translation>
    </message>
    <message>
        <source>Click a step to select it</source>
        <translation>Haga clic en una etapa para seleccionarla</translation>
    </message>
    <message>
        <source>&amp;Receptivity:</source>
        <translation>&amp;Receptividad:</translation>
    </message>
    <message>
        <source>e.g. PartPresent AND X3, ↑Start, 5s/X2</source>
        <translation>p. ej. PartPresent AND X3, ↑Start, 5s/X2</translation>
    </message>
    <message>
        <source>Structured Text as in GEMMA conditions, plus X3 (step 3 is active), ↑a or RE a (rising edge), ↓a or FE a (falling edge), 5s/X3 (step 3 active for 5 s) and Complete.
Ctrl+Space completes a name.</source>
        <translation>Texto estructurado como en las condiciones GEMMA, más X3 (la etapa 3 está activa), ↑a o RE a (flanco ascendente), ↓a o FE a (flanco descendente), 5s/X3 (la etapa 3 lleva 5 s activa) y Complete.
Ctrl+Espacio completa un nombre.</translation>
    </message>
    <message>
        <source>%1 T%2</source>
        <extracomment>A transition of the nested GRAFCET of a GEMMA step: &quot;F1 T2&quot;</extracomment>
        <translation>%1 T%2</translation>
    </message>
    <message>
        <source>In the nested GRAFCET of %1 %2</source>
        <translation>En el GRAFCET anidado de %1 %2</translation>
    </message>
</context>
<context>
    <name>editor::LinkDrag</name>
    <message>
        <source>A transition cannot be linked to a transition: steps and transitions alternate</source>
        <translation>Una transición no se puede enlazar con una transición: etapas y transiciones se alternan</translation>
    </message>
    <message>
        <source>Step %1 already leads to step %2</source>
        <translation>La etapa %1 ya lleva a la etapa %2</translation>
    </message>
    <message>
        <source>Step %1 already precedes T%2</source>
        <translation>La etapa %1 ya precede a T%2</translation>
    </message>
    <message>
        <source>Step %1 already follows T%2</source>
        <translation>La etapa %1 ya sigue a T%2</translation>
    </message>
    <message>
        <source>Step %1 cannot be linked to itself through one transition</source>
        <translation>La etapa %1 no se puede enlazar consigo misma a través de una sola transición</translation>
    </message>
    <message>
        <source>Step %1 would be linked to itself through T%2</source>
        <translation>La etapa %1 quedaría enlazada consigo misma a través de T%2</translation>
    </message>
    <message>
        <source>Drag onto a step or a transition to link them</source>
        <translation>Arrastre hasta una etapa o una transición para enlazarlas</translation>
    </message>
    <message>
        <source>Link step %1 to step %2 in %3</source>
        <translation>Enlazar la etapa %1 con la etapa %2 en %3</translation>
    </message>
    <message>
        <source>Link step %1 to T%2 in %3</source>
        <translation>Enlazar la etapa %1 con T%2 en %3</translation>
    </message>
    <message>
        <source>Link T%1 to step %2 in %3</source>
        <translation>Enlazar T%1 con la etapa %2 en %3</translation>
    </message>
</context>
<context>
    <name>editor::MachineDock</name>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Añadir</translation>
    </message>
    <message>
        <source>Add a component of the kind chosen beside</source>
        <translation>Añadir un componente del tipo elegido al lado</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>Remove the selected component and its wiring</source>
        <translation>Quitar el componente seleccionado y su cableado</translation>
    </message>
    <message>
        <source>The model has no machine yet. Add its components to simulate in closed loop: the machine then sets the sensors.</source>
        <translation>El modelo aún no tiene máquina. Añada sus componentes para simular en lazo cerrado: la máquina fija entonces los sensores.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>(not wired)</source>
        <translation>(sin cablear)</translation>
    </message>
    <message>
        <source>A BOOL output of the program, which drives the component</source>
        <translation>Una salida BOOL del programa, que acciona el componente</translation>
    </message>
    <message>
        <source>A BOOL input of the program, which the component sets</source>
        <translation>Una entrada BOOL del programa, que el componente fija</translation>
    </message>
    <message>
        <source>Unlimited</source>
        <translation>Ilimitado</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>Contacto</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(ninguno)</translation>
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
        <translation>Máquina</translation>
    </message>
    <message>
        <source>The virtual machine: its components, moving as the simulation runs</source>
        <translation>La máquina virtual: sus componentes, que se mueven durante la simulación</translation>
    </message>
</context>
<context>
    <name>editor::MainWindow</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Error en el guardado automático: %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Ay&amp;uda</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nuevo</translation>
    </message>
    <message>
        <source>Start a new model from the GEMMA template</source>
        <translation>Empezar un modelo nuevo a partir de la plantilla GEMMA</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Abrir…</translation>
    </message>
    <message>
        <source>Open a GG Studio model, a GG-Generator file or an exported PLCopen XML file</source>
        <translation>Abrir un modelo de GG Studio, un archivo de GG-Generator o un archivo PLCopen XML exportado</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Guardar</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Guardar &amp;como…</translation>
    </message>
    <message>
        <source>&amp;Reset to Template…</source>
        <translation>Restablecer la p&amp;lantilla…</translation>
    </message>
    <message>
        <source>Put every state, transition, variable and setting back to the template</source>
        <translation>Devolver cada estado, transición, variable y ajuste a los de la plantilla</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Deshacer</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Deshacer %1</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rehacer</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Rehacer %1</translation>
    </message>
    <message>
        <source>&amp;Model Settings…</source>
        <translation>&amp;Ajustes del modelo…</translation>
    </message>
    <message>
        <source>Model name, PLC cycle time and code dialect</source>
        <translation>Nombre del modelo, tiempo de ciclo del PLC y dialecto del código</translation>
    </message>
    <message>
        <source>Show &amp;Hidden Elements</source>
        <translation>Mostrar los elementos &amp;ocultos</translation>
    </message>
    <message>
        <source>Draw the hidden states and transitions faded, so they can be selected</source>
        <translation>Dibujar atenuados los estados y transiciones ocultos, para poder seleccionarlos</translation>
    </message>
    <message>
        <source>&amp;Actual Size (100 %)</source>
        <translation>&amp;Tamaño real (100 %)</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>A&amp;mpliar</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Re&amp;ducir</translation>
    </message>
    <message>
        <source>&amp;About GG Studio</source>
        <translation>&amp;Acerca de GG Studio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Acerca de &amp;Qt</translation>
    </message>
    <message>
        <source>%1[*] — GG Studio</source>
        <translation>%1[*] — GG Studio</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Cambios no guardados</translation>
    </message>
    <message>
        <source>The model “%1” has unsaved changes.</source>
        <translation>El modelo «%1» tiene cambios sin guardar.</translation>
    </message>
    <message>
        <source>Do you want to save them?</source>
        <translation>¿Desea guardarlos?</translation>
    </message>
    <message>
        <source>All supported files (*.json *.xml)</source>
        <translation>Todos los archivos compatibles (*.json *.xml)</translation>
    </message>
    <message>
        <source>GG Studio models (*.json)</source>
        <translation>Modelos de GG Studio (*.json)</translation>
    </message>
    <message>
        <source>GG-Generator files (*.json)</source>
        <translation>Archivos de GG-Generator (*.json)</translation>
    </message>
    <message>
        <source>GG Studio PLCopen XML (*.xml)</source>
        <translation>PLCopen XML de GG Studio (*.xml)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Open Model</source>
        <translation>Abrir un modelo</translation>
    </message>
    <message>
        <source>Could not open %1.</source>
        <translation>No se ha podido abrir %1.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Se ha abierto %1</translation>
    </message>
    <message>
        <source>Imported %1: Save As keeps it as a GG Studio model</source>
        <translation>Se ha importado %1: «Guardar como» lo conserva como modelo de GG Studio</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>sin título</translation>
    </message>
    <message>
        <source>Save Model As</source>
        <translation>Guardar el modelo como</translation>
    </message>
    <message>
        <source>Save Model</source>
        <translation>Guardar el modelo</translation>
    </message>
    <message>
        <source>Could not save %1.</source>
        <translation>No se ha podido guardar %1.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Se ha guardado %1</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Error al exportar</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>No se ha podido escribir %1.</translation>
    </message>
    <message>
        <source>Recovered unsaved changes: save them to keep them</source>
        <translation>Cambios no guardados recuperados: guárdelos para conservarlos</translation>
    </message>
    <message>
        <source>Reset to Template</source>
        <translation>Restablecer la plantilla</translation>
    </message>
    <message>
        <source>Put every state, transition, variable and setting back to the GEMMA template? You can undo this.</source>
        <translation>¿Devolver cada estado, transición, variable y ajuste a los de la plantilla GEMMA? Podrá deshacerlo.</translation>
    </message>
    <message>
        <source>About GG Studio</source>
        <translation>Acerca de GG Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;GG Studio %1&lt;/h3&gt;&lt;p&gt;An editor for the GEMMA-GRAFCET method: choose the operating modes of a machine on the GEMMA template, write the conditions of their transitions, and generate the IEC 61131-3 program that runs them (Structured Text, PLCopen XML).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;GG Studio %1&lt;/h3&gt;&lt;p&gt;Un editor para el método GEMMA-GRAFCET: elija los modos de marcha y parada de una máquina sobre la plantilla GEMMA, escriba las condiciones de sus transiciones y genere el programa IEC 61131-3 que los ejecuta (texto estructurado (ST), PLCopen XML).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulación</translation>
    </message>
    <message>
        <source>&amp;Simulate</source>
        <translation>&amp;Simular</translation>
    </message>
    <message>
        <source>Run the model scan by scan; editing is locked while the simulation is on</source>
        <translation>Ejecutar el modelo ciclo a ciclo; la edición queda bloqueada durante la simulación</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Ejecutar</translation>
    </message>
    <message>
        <source>Run scans at the speed set in the Simulation dock, or pause them</source>
        <translation>Ejecutar los ciclos a la velocidad fijada en el panel Simulación, o pausarlos</translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation>&amp;Un ciclo</translation>
    </message>
    <message>
        <source>R&amp;eset Simulation</source>
        <translation>&amp;Reiniciar la simulación</translation>
    </message>
    <message>
        <source>Simulation: editing locked</source>
        <translation>Simulación: edición bloqueada</translation>
    </message>
    <message>
        <source>&amp;Verify</source>
        <translation>&amp;Verificar</translation>
    </message>
    <message>
        <source>Verifying…</source>
        <translation>Verificando…</translation>
    </message>
    <message>
        <source>Verification failed: %1</source>
        <translation>La verificación ha fallado: %1</translation>
    </message>
    <message>
        <source>Verification finished: some properties do not hold (see Problems)</source>
        <translation>Verificación terminada: algunas propiedades no se cumplen (ver Problemas)</translation>
    </message>
    <message>
        <source>Verification finished: every property holds</source>
        <translation>Verificación terminada: se cumplen todas las propiedades</translation>
    </message>
    <message>
        <source>%1 counterexample</source>
        <translation>contraejemplo %1</translation>
    </message>
    <message>
        <source>Replay in Simulator</source>
        <translation>Reproducir en el simulador</translation>
    </message>
    <message>
        <source>Could not replay %1.</source>
        <translation>No se ha podido reproducir %1.</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>E&amp;jemplos</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>&amp;Restablecer la disposición</translation>
    </message>
    <message>
        <source>Put the panels and the toolbar back where they were at the first start</source>
        <translation>Devolver los paneles y la barra de herramientas adonde estaban en el primer inicio</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Barra de herramientas principal</translation>
    </message>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Exportar a PLCopen XML</translation>
    </message>
    <message>
        <source>Open Example</source>
        <translation>Abrir un ejemplo</translation>
    </message>
    <message>
        <source>Could not open the example “%1”.</source>
        <translation>No se ha podido abrir el ejemplo «%1».</translation>
    </message>
    <message>
        <source>Opened the example “%1” as an untitled copy: Save As keeps your changes</source>
        <translation>Se ha abierto el ejemplo «%1» como copia sin título: «Guardar como» conserva sus cambios</translation>
    </message>
    <message>
        <source>&amp;Hide Selected Elements</source>
        <translation>&amp;Ocultar los elementos seleccionados</translation>
    </message>
    <message>
        <source>Hide the selected states and transitions: the machine does not need them</source>
        <translation>Ocultar los estados y transiciones seleccionados: la máquina no los necesita</translation>
    </message>
    <message>
        <source>Sho&amp;w Selected Elements</source>
        <translation>&amp;Mostrar los elementos seleccionados</translation>
    </message>
    <message>
        <source>Show the selected hidden states and transitions again</source>
        <translation>Volver a mostrar los estados y transiciones ocultos seleccionados</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Guía del usuario</translation>
    </message>
    <message>
        <source>How to build a model, simulate, verify and export, offline; F1 opens it at the part about the panel you are in</source>
        <translation>Cómo crear un modelo, simularlo, verificarlo y exportarlo, sin conexión (en inglés); F1 la abre en la parte del panel en el que está</translation>
    </message>
    <message>
        <source>Step &amp;Back</source>
        <translation>Ciclo &amp;anterior</translation>
    </message>
    <message>
        <source>Show the previous scan of the run; a scan or Run from there continues from it and drops the later scans</source>
        <translation>Mostrar el ciclo anterior de la ejecución; un ciclo o Ejecutar desde ahí continúa a partir de él y descarta los ciclos posteriores</translation>
    </message>
    <message>
        <source>Step &amp;Forward</source>
        <translation>Ciclo si&amp;guiente</translation>
    </message>
    <message>
        <source>Show the next scan of the run&apos;s history</source>
        <translation>Mostrar el ciclo siguiente del historial de la ejecución</translation>
    </message>
    <message>
        <source>Prove what the GEMMA layer and the nested GRAFCETs can and cannot do for every input sequence, and check your properties; the findings go to the Problems dock</source>
        <translation>Demostrar lo que el nivel GEMMA y los GRAFCET anidados pueden y no pueden hacer para toda secuencia de entradas, y comprobar sus propiedades; los hallazgos van al panel Problemas</translation>
    </message>
    <message>
        <source>Verify with &amp;Exact Time</source>
        <translation>Verificar con tiempo e&amp;xacto</translation>
    </message>
    <message>
        <source>Count time in scans when verifying: every timer elapses exactly when the PLC&apos;s would, instead of &quot;may or may not have elapsed&quot; (more states)</source>
        <translation>Contar el tiempo en ciclos al verificar: cada temporizador vence exactamente cuando vencería el del autómata, en lugar de &quot;puede haber vencido o no&quot; (más estados)</translation>
    </message>
    <message>
        <source>%1 was opened, but not everything in the file was taken over.</source>
        <translation>%1 se ha abierto, pero no todo el contenido del archivo se ha incorporado.</translation>
    </message>
    <message>
        <source>Verification finished: nothing is violated, but some properties are undecided (see Problems)</source>
        <translation>Verificación terminada: nada se incumple, pero algunas propiedades están sin decidir (ver Problemas)</translation>
    </message>
    <message>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Ajustar a la ventana</translation>
    </message>
    <message>
        <source>Put every command, unit mode, GRAFCET, variable and setting back to a new PackML model of this edition? You can undo this.</source>
        <translation>¿Devolver cada comando, modo de unidad, GRAFCET, variable y ajuste a un nuevo modelo PackML de esta edición? Puede deshacerlo.</translation>
    </message>
    <message>
        <source>Verify with the &amp;Machine</source>
        <translation>Verificar con la &amp;máquina</translation>
    </message>
    <message>
        <source>Explore the program with the model&apos;s machine: the sensors it drives follow the cylinders and conveyors instead of taking any value</source>
        <translation>Explorar el programa con la máquina del modelo: los sensores que mueve siguen a los cilindros y transportadores en lugar de tomar cualquier valor</translation>
    </message>
    <message>
        <source>Verification cancelled: the model, the Complete settings, the machine&apos;s use or Exact Time changed</source>
        <translation>Verificación cancelada: cambiaron el modelo, los ajustes de Complete, el uso de la máquina o el tiempo exacto</translation>
    </message>
    <message>
        <source>Co&amp;nnect…</source>
        <translation>Co&amp;nectar…</translation>
    </message>
    <message>
        <source>Link the simulation to a digital twin, a soft PLC or an HMI over Modbus TCP; it then runs in real time</source>
        <translation>Enlazar la simulación con un gemelo digital, un PLC por software o una HMI por Modbus TCP; entonces se ejecuta en tiempo real</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Desconectar</translation>
    </message>
    <message>
        <source>End the Modbus TCP link</source>
        <translation>Terminar el enlace Modbus TCP</translation>
    </message>
    <message>
        <source>Verify with Single &amp;Faults</source>
        <translation>Verificar con &amp;fallos únicos</translation>
    </message>
    <message>
        <source>With the machine, also explore any one fault from any scan on: a sensor stuck or flickering, a cylinder or conveyor jammed</source>
        <translation>Con la máquina, explorar también un fallo cualquiera a partir de cualquier ciclo: un sensor bloqueado o intermitente, un cilindro o una cinta atascados</translation>
    </message>
    <message>
        <source>The Modbus link is for GEMMA models; PackML models are not linked yet</source>
        <translation>El enlace Modbus es para modelos GEMMA; los modelos PackML aún no se enlazan</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
    <message>
        <source>The Modbus link could not start: %1</source>
        <translation>El enlace Modbus no pudo iniciarse: %1</translation>
    </message>
    <message>
        <source>Undo</source>
        <extracomment>the Undo button of the toolbar (the Edit menu names the command)</extracomment>
        <translation>Deshacer</translation>
    </message>
    <message>
        <source>Redo</source>
        <extracomment>the Redo button of the toolbar (the Edit menu names the command)</extracomment>
        <translation>Rehacer</translation>
    </message>
    <message>
        <source>Undo %1</source>
        <translation>Deshacer %1</translation>
    </message>
    <message>
        <source>Redo %1</source>
        <translation>Rehacer %1</translation>
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
        <translation>Entrada discreta</translation>
    </message>
    <message>
        <source>Holding register</source>
        <translation>Registro de retención</translation>
    </message>
    <message>
        <source>Input register</source>
        <translation>Registro de entrada</translation>
    </message>
    <message>
        <source>Connect over Modbus TCP</source>
        <translation>Conectar por Modbus TCP</translation>
    </message>
    <message>
        <source>Server: the twin connects to the simulator</source>
        <translation>Servidor: el gemelo se conecta al simulador</translation>
    </message>
    <message>
        <source>Client: the simulator connects to the twin</source>
        <translation>Cliente: el simulador se conecta al gemelo</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabla</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Dirección</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Modo:</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Puerto:</translation>
    </message>
    <message>
        <source>Unit id:</source>
        <translation>Id. de unidad:</translation>
    </message>
    <message>
        <source>Load CSV…</source>
        <translation>Cargar CSV…</translation>
    </message>
    <message>
        <source>Save As CSV…</source>
        <translation>Guardar como CSV…</translation>
    </message>
    <message>
        <source>Default Map</source>
        <translation>Mapa predeterminado</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
    <message>
        <source>Map (each table numbered from 0 in declaration order unless loaded):</source>
        <translation>Mapa (cada tabla numerada desde 0 en el orden de declaración, salvo si se carga):</translation>
    </message>
    <message>
        <source>Load Modbus Map</source>
        <translation>Cargar mapa Modbus</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message>
        <source>Save Modbus Map</source>
        <translation>Guardar mapa Modbus</translation>
    </message>
    <message>
        <source>Line %1, column %2: %3</source>
        <translation>Línea %1, columna %2: %3</translation>
    </message>
    <message>
        <source>%1 cannot be used:</source>
        <translation>%1 no se puede usar:</translation>
    </message>
    <message>
        <source>%1 could not be saved: %2</source>
        <translation>%1 no se pudo guardar: %2</translation>
    </message>
</context>
<context>
    <name>editor::ModbusConnection</name>
    <message>
        <source>The simulation could not start.</source>
        <translation>La simulación no pudo iniciarse.</translation>
    </message>
    <message>
        <source>Modbus server on %1, unit %2, clients connected: %3</source>
        <translation>Servidor Modbus en %1, unidad %2, clientes conectados: %3</translation>
    </message>
    <message>
        <source>Modbus client of %1: connected</source>
        <translation>Cliente Modbus de %1: conectado</translation>
    </message>
    <message>
        <source>Modbus client of %1: connecting</source>
        <translation>Cliente Modbus de %1: conectando</translation>
    </message>
    <message>
        <source>Modbus client of %1: not connected, trying again</source>
        <translation>Cliente Modbus de %1: no conectado, reintentando</translation>
    </message>
    <message>
        <source>Set by the twin: %1</source>
        <translation>Puesto por el gemelo: %1</translation>
    </message>
    <message>
        <source>Errors: %1, the last: %2</source>
        <translation>Errores: %1, el último: %2</translation>
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
        <translation>Ajustes del modelo</translation>
    </message>
    <message>
        <source>The project name written into the exported PLCopen XML</source>
        <translation>El nombre del proyecto que se escribe en el PLCopen XML exportado</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>The period of the cyclic PLC task that runs GEMMA</source>
        <translation>El periodo de la tarea cíclica del PLC que ejecuta GEMMA</translation>
    </message>
    <message>
        <source>The flavour of the generated Structured Text and its preview</source>
        <translation>La variante del texto estructurado (ST) generado y de su vista previa</translation>
    </message>
    <message>
        <source>Use the cycle time and dialect for &amp;new models</source>
        <translation>Usar este tiempo de ciclo y este dialecto para los &amp;modelos nuevos</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <source>PLC &amp;cycle time:</source>
        <translation>Tiempo de &amp;ciclo del PLC:</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialecto:</translation>
    </message>
    <message>
        <source>Change model settings</source>
        <translation>Cambiar los ajustes del modelo</translation>
    </message>
    <message>
        <source>One evolution per scan</source>
        <translation>Una evolución por ciclo</translation>
    </message>
    <message>
        <source>Until stable</source>
        <translation>Hasta la estabilidad</translation>
    </message>
    <message>
        <source>How a nested GRAFCET evolves in one call of its function block</source>
        <translation>Cómo evoluciona un GRAFCET anidado en una llamada de su bloque de función</translation>
    </message>
    <message>
        <source>&amp;Evolution rule:</source>
        <translation>Regla de &amp;evolución:</translation>
    </message>
    <message>
        <source>Each scan repeats evolutions until no transition can fire (IEC 60848&apos;s search for stability), at most one more than the GRAFCET has transitions; if the last one still fires, the function block reports Unstable.</source>
        <translation>Cada ciclo repite evoluciones hasta que ninguna transición puede franquearse (la búsqueda de estabilidad de IEC 60848), como mucho una más de las transiciones que tiene el GRAFCET; si la última aún franquea, el bloque de función indica Unstable.</translation>
    </message>
    <message>
        <source>Each scan fires the transitions enabled at its start once, as SFC runtimes such as CODESYS do.</source>
        <translation>Cada ciclo franquea una vez las transiciones validadas al empezar, como hacen los entornos SFC como CODESYS.</translation>
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
        <translation>La guía GEMMA (procedimientos de parada, de funcionamiento y de fallo) con un GRAFCET anidado en cada macroetapa: el método GEMMA-GRAFCET.</translation>
    </message>
    <message>
        <source>PackML, 2015 edition</source>
        <translation>PackML, edición 2015</translation>
    </message>
    <message>
        <source>The ISA-TR88.00.02-2015 state machine with unit modes: Production, Maintenance and Manual, a GRAFCET in each acting state.</source>
        <translation>La máquina de estados ISA-TR88.00.02-2015 con modos de unidad: Production, Maintenance y Manual, un GRAFCET en cada estado activo.</translation>
    </message>
    <message>
        <source>PackML, 2022 edition</source>
        <translation>PackML, edición 2022</translation>
    </message>
    <message>
        <source>The ISA-TR88.00.02-2022 state machine: as 2015, with the Complete command that ends Execute.</source>
        <translation>La máquina de estados ISA-TR88.00.02-2022: como la de 2015, con el comando Complete que termina Execute.</translation>
    </message>
    <message>
        <source>New Model</source>
        <translation>Nuevo modelo</translation>
    </message>
    <message>
        <source>Which chart does the new model fill in?</source>
        <translation>¿Qué diagrama rellena el nuevo modelo?</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartContextMenu</name>
    <message>
        <source>&amp;Open GRAFCET</source>
        <translation>&amp;Abrir el GRAFCET</translation>
    </message>
    <message>
        <source>&amp;Choose Its GRAFCET…</source>
        <translation>&amp;Elegir su GRAFCET…</translation>
    </message>
    <message>
        <source>Its own GRAFCET in this mode, the one of another mode, or none</source>
        <translation>Su propio GRAFCET en este modo, el de otro modo, o ninguno</translation>
    </message>
    <message>
        <source>Edit the %1 &amp;Condition…</source>
        <translation>Editar la &amp;condición de %1…</translation>
    </message>
    <message>
        <source>Show in &amp;Mode</source>
        <translation>Mostrar en el &amp;modo</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartTexts</name>
    <message>
        <source>Disabled in mode %1: never active there.</source>
        <extracomment>%1: the unit mode the chart shows (&quot;3 Manual&quot;)</extracomment>
        <translation>Desactivado en el modo %1: nunca activo en él.</translation>
    </message>
    <message>
        <source>Runs its own nested GRAFCET in this mode.</source>
        <translation>Ejecuta su propio GRAFCET anidado en este modo.</translation>
    </message>
    <message>
        <source>Runs the nested GRAFCET of mode %1 for this state.</source>
        <extracomment>%1: the number of the unit mode whose GRAFCET runs</extracomment>
        <translation>Ejecuta el GRAFCET anidado del modo %1 para este estado.</translation>
    </message>
    <message>
        <source>No nested GRAFCET in this mode: it waits for a command.</source>
        <translation>Sin GRAFCET anidado en este modo: espera una orden.</translation>
    </message>
    <message>
        <source>No nested GRAFCET in this mode: it completes at once.</source>
        <translation>Sin GRAFCET anidado en este modo: termina de inmediato.</translation>
    </message>
    <message>
        <source>SC (State Complete): %1 has done its work.</source>
        <extracomment>%1: a PackML state (&quot;Starting&quot;)</extracomment>
        <translation>SC (State Complete): %1 ha terminado su trabajo.</translation>
    </message>
    <message>
        <source>Optional: exists only under an option of Model Settings.</source>
        <translation>Opcional: solo existe con una opción de la configuración del modelo.</translation>
    </message>
    <message>
        <source>In mode %1, %2 is disabled: this transition leads to %3.</source>
        <extracomment>%1: the unit mode (&quot;3 Manual&quot;), %2: the disabled state, %3: where the transition leads instead</extracomment>
        <translation>En el modo %1, %2 está desactivado: esta transición lleva a %3.</translation>
    </message>
    <message>
        <source>Accepted by every state in the Abort frame, before their own transitions.</source>
        <translation>Aceptada por todos los estados del marco Abort, antes de sus propias transiciones.</translation>
    </message>
    <message>
        <source>Accepted by every state in the Stop frame, before their own transitions.</source>
        <translation>Aceptada por todos los estados del marco Stop, antes de sus propias transiciones.</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Condición:</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartView</name>
    <message>
        <source>Unit &amp;mode:</source>
        <translation>&amp;Modo de la unidad:</translation>
    </message>
    <message>
        <source>The unit mode the chart shows: its disabled states greyed, its skipped transitions labelled with where they lead</source>
        <translation>El modo de la unidad que muestra el diagrama: sus estados desactivados en gris, sus transiciones saltadas rotuladas con su destino</translation>
    </message>
</context>
<context>
    <name>editor::PackmlCommandsDock</name>
    <message>
        <source>Commands</source>
        <translation>Comandos</translation>
    </message>
    <message>
        <source>Commands belong to PackML models: this model follows GEMMA.</source>
        <translation>Los comandos son de los modelos PackML: este modelo sigue la GEMMA.</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>a PackML command&apos;s row: its PackTags number and name, &quot;4 Hold&quot;</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Condición:</translation>
    </message>
    <message>
        <source>e.g. %1, or FALSE for a command given only through CntrlCmd</source>
        <translation>p. ej. %1, o FALSE para un comando dado solo por CntrlCmd</translation>
    </message>
    <message>
        <source>Issues the command at its rising edge. Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND, XOR, OR, comparisons.
Ctrl+Space completes a variable name.</source>
        <translation>Da el comando en su flanco ascendente. Texto estructurado: variables declaradas, números, TRUE, FALSE, NOT, AND, XOR, OR, comparaciones.
Ctrl+Espacio completa un nombre de variable.</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Comentario:</translation>
    </message>
    <message>
        <source>Where the command comes from on this machine</source>
        <translation>De dónde viene el comando en esta máquina</translation>
    </message>
</context>
<context>
    <name>editor::PackmlModeForm</name>
    <message>
        <source>Name:</source>
        <translation>Nombre:</translation>
    </message>
    <message>
        <source>User modes (4 to 31) take an IEC identifier that no other mode has and the generated code does not use; it becomes part of function block names.
Modes 1 to 3 are Production, Maintenance and Manual.</source>
        <translation>Los modos de usuario (4 a 31) llevan un identificador IEC que ningún otro modo tiene y que el código generado no usa; forma parte de los nombres de los bloques de función.
Los modos 1 a 3 son Production, Maintenance y Manual.</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Comentario:</translation>
    </message>
    <message>
        <source>What the unit does in this mode</source>
        <translation>Lo que hace la unidad en este modo</translation>
    </message>
    <message>
        <source>Request condition:</source>
        <translation>Condición de solicitud:</translation>
    </message>
    <message>
        <source>None: requested through UnitMode only (e.g. KeyManual)</source>
        <translation>Ninguna: solicitado solo por UnitMode (p. ej. KeyManual)</translation>
    </message>
    <message>
        <source>Requests this mode at its rising edge, as a rising edge of UnitModeChangeRequest with UnitMode set to its number does.</source>
        <translation>Solicita este modo en su flanco ascendente, como lo hace un flanco ascendente de UnitModeChangeRequest con UnitMode en su número.</translation>
    </message>
    <message>
        <source>Disabled states</source>
        <translation>Estados desactivados</translation>
    </message>
    <message>
        <source>Stopped, Idle, Execute and Aborted are never disabled. Disabling Held, Suspended or Complete disables the acting states of its loop; enabling one of those enables it again.</source>
        <translation>Stopped, Idle, Execute y Aborted nunca se desactivan. Desactivar Held, Suspended o Complete desactiva los estados activos de su bucle; activar uno de ellos lo vuelve a activar.</translation>
    </message>
    <message>
        <source>Mode change allowed in</source>
        <translation>Cambio de modo permitido en</translation>
    </message>
    <message>
        <source>A change to or from this mode is granted in a state that both modes list and the requested mode enables.</source>
        <translation>Un cambio hacia o desde este modo se concede en un estado que ambos modos listan y que el modo solicitado activa.</translation>
    </message>
    <message>
        <source>%1 is disabled in this mode: no change can be granted there.</source>
        <translation>%1 está desactivado en este modo: ahí no se puede conceder ningún cambio.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlModesDock</name>
    <message>
        <source>Modes</source>
        <translation>Modos</translation>
    </message>
    <message>
        <source>Unit modes belong to PackML models: this model follows GEMMA.</source>
        <translation>Los modos de unidad son de los modelos PackML: este modelo sigue la GEMMA.</translation>
    </message>
    <message>
        <source>The number of the next user mode (PackTags UnitMode)</source>
        <translation>El número del próximo modo de usuario (PackTags UnitMode)</translation>
    </message>
    <message>
        <source>&amp;Add Mode</source>
        <translation>&amp;Añadir modo</translation>
    </message>
    <message>
        <source>Adds a user mode with this number: every state enabled, mode changes in Stopped, Idle and Aborted</source>
        <translation>Añade un modo de usuario con este número: todos los estados activados, cambios de modo en Stopped, Idle y Aborted</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Eliminar</translation>
    </message>
    <message>
        <source>&amp;Initial mode:</source>
        <translation>Modo &amp;inicial:</translation>
    </message>
    <message>
        <source>The mode the unit is in at power-up</source>
        <translation>El modo de la unidad al arrancar</translation>
    </message>
    <message>
        <source>Production is the mode every unit has</source>
        <translation>Production es el modo que tiene toda unidad</translation>
    </message>
    <message>
        <source>Removes the mode with its GRAFCETs</source>
        <translation>Elimina el modo con sus GRAFCET</translation>
    </message>
</context>
<context>
    <name>editor::PackmlSettingsWidget</name>
    <message>
        <source>&amp;Hold accepted in Suspended</source>
        <translation>&amp;Hold aceptado en Suspended</translation>
    </message>
    <message>
        <source>Suspended → Holding on Hold, an optional transition of the 2015 model and a standard one of 2022</source>
        <translation>Suspended → Holding con Hold, una transición opcional del modelo 2015 y estándar en 2022</translation>
    </message>
    <message>
        <source>C&amp;omplete accepted in Suspended and Held</source>
        <translation>C&amp;omplete aceptado en Suspended y Held</translation>
    </message>
    <message>
        <source>Suspended and Held → Completing on the Complete command (2022 edition only)</source>
        <translation>Suspended y Held → Completing con el comando Complete (solo edición 2022)</translation>
    </message>
    <message>
        <source>The state at power-up: Stopped as usual, Aborted for a unit that must be cleared after a power loss, Idle for one with nothing to reset</source>
        <translation>El estado al arrancar: Stopped lo habitual, Aborted para una unidad que debe rearmarse tras un corte de corriente, Idle para una sin nada que reiniciar</translation>
    </message>
    <message>
        <source>PackML &amp;edition:</source>
        <translation>&amp;Edición PackML:</translation>
    </message>
    <message>
        <source>Initial &amp;state:</source>
        <translation>E&amp;stado inicial:</translation>
    </message>
    <message>
        <source>2022: Execute is left on the Complete command, which a new model conditions on Cmd_Complete; its State Complete leads nowhere.</source>
        <translation>2022: se sale de Execute con el comando Complete, que un modelo nuevo condiciona a Cmd_Complete; su State Complete no lleva a ninguna parte.</translation>
    </message>
    <message>
        <source>2015: Execute&apos;s State Complete leads to Completing; there is no Complete command.</source>
        <translation>2015: el State Complete de Execute lleva a Completing; no hay comando Complete.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlSimulationDock</name>
    <message>
        <source>PackML Simulation</source>
        <translation>Simulación PackML</translation>
    </message>
    <message>
        <source>Start Simulation</source>
        <translation>Iniciar la simulación</translation>
    </message>
    <message>
        <source>Run or pause the scans</source>
        <translation>Ejecutar o pausar los ciclos</translation>
    </message>
    <message>
        <source>Single scan</source>
        <translation>Un solo ciclo</translation>
    </message>
    <message>
        <source>Step back: show the scan before</source>
        <translation>Retroceder: mostrar el ciclo anterior</translation>
    </message>
    <message>
        <source>Step forward: show the scan after</source>
        <translation>Avanzar: mostrar el ciclo siguiente</translation>
    </message>
    <message>
        <source>Reset: the initial state and mode, inputs at their defaults</source>
        <translation>Reiniciar: el estado y el modo iniciales, las entradas a sus valores por defecto</translation>
    </message>
    <message>
        <source>End the simulation</source>
        <translation>Terminar la simulación</translation>
    </message>
    <message>
        <source>Scans/s:</source>
        <translation>Ciclos/s:</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidad</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>Traza</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Escenario</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Comandos</translation>
    </message>
    <message>
        <source>Unit mode</source>
        <translation>Modo de la unidad</translation>
    </message>
    <message>
        <source>Pick a mode to request it: the mode manager grants it or says why not</source>
        <translation>Elija un modo para solicitarlo: el gestor de modos lo concede o dice por qué no</translation>
    </message>
    <message>
        <source>Function block</source>
        <translation>Bloque de función</translation>
    </message>
    <message>
        <source>SC from the skeleton</source>
        <extracomment>the State Complete of a state without nested GRAFCET: as the generated skeleton sets it</extracomment>
        <translation>SC del esqueleto</translation>
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
        <translation>El State Complete de un estado sin GRAFCET anidado, asignado a mano para retener un estado activo o completar Execute</translation>
    </message>
    <message>
        <source>Replay Scenario…</source>
        <translation>Reproducir un escenario…</translation>
    </message>
    <message>
        <source>Start the simulation to play the unit&apos;s commands and modes.</source>
        <translation>Inicie la simulación para ejecutar los comandos y modos de la unidad.</translation>
    </message>
    <message>
        <source>Scan %1: %2 in %3</source>
        <extracomment>%1: a scan number, %2: a PackML state (Execute), %3: a unit mode (Production)</extracomment>
        <translation>Ciclo %1: %2 en %3</translation>
    </message>
    <message>
        <source>%1 (history; the latest scan is %2)</source>
        <extracomment>%1: a status, %2: the latest scan</extracomment>
        <translation>%1 (historial; el último ciclo es %2)</translation>
    </message>
    <message>
        <source>%1 is accepted in %2</source>
        <translation>%1 se acepta en %2</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2: pressing it shows why</source>
        <translation>%1 no se acepta en %2: al pulsarlo se muestra por qué</translation>
    </message>
    <message>
        <source>%1: requested, read by the next scan</source>
        <translation>%1: solicitado, lo leerá el próximo ciclo</translation>
    </message>
    <message>
        <source>%1 is a wait state: no function block runs in it</source>
        <translation>%1 es un estado de espera: no se ejecuta en él ningún bloque de función</translation>
    </message>
    <message>
        <source>%1: active steps %2, Complete = %3</source>
        <extracomment>%1: a function block instance (Production_Execute), %2: step numbers, %3: TRUE or FALSE</extracomment>
        <translation>%1: etapas activas %2, Complete = %3</translation>
    </message>
    <message>
        <source>%1 runs no GRAFCET: Complete = %2</source>
        <translation>%1 no ejecuta ningún GRAFCET: Complete = %2</translation>
    </message>
    <message>
        <source>Replaying %1: scan %2 of %3</source>
        <extracomment>%1: a scenario file, %2: the scan shown, %3: its last scan</extracomment>
        <translation>Reproduciendo %1: ciclo %2 de %3</translation>
    </message>
    <message>
        <source>%1 passed: all %2 expectation(s) met</source>
        <translation>%1 superado: se cumplen las %2 expectativa(s)</translation>
    </message>
    <message>
        <source>%1 failed: %2 of %3 expectation(s) did not hold</source>
        <translation>%1 fallido: %2 de %3 expectativa(s) no se cumplieron</translation>
    </message>
    <message>
        <source>Cannot replay %1:
%2</source>
        <translation>No se puede reproducir %1:
%2</translation>
    </message>
    <message>
        <source>Replay Scenario</source>
        <translation>Reproducir un escenario</translation>
    </message>
    <message>
        <source>Scenarios (*.scenario *.txt);;All files (*)</source>
        <translation>Escenarios (*.scenario *.txt);;Todos los archivos (*)</translation>
    </message>
</context>
<context>
    <name>editor::PackmlStateDock</name>
    <message>
        <source>State</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Select a state in the PackML chart to see what it means and what runs in it.</source>
        <translation>Seleccione un estado en el diagrama PackML para ver qué significa y qué se ejecuta en él.</translation>
    </message>
    <message>
        <source>Nested GRAFCET per mode</source>
        <translation>GRAFCET anidado por modo</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>a PackML state&apos;s title: its PackTags number and name, &quot;6 Execute&quot;</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Own: a nested GRAFCET for this mode; Same as: the one of another mode; None: the state&apos;s skeleton (%1).</source>
        <translation>Propio: un GRAFCET anidado para este modo; Igual que: el de otro modo; Ninguno: el esqueleto del estado (%1).</translation>
    </message>
    <message>
        <source>Execute waits for a command</source>
        <translation>Execute espera un comando</translation>
    </message>
    <message>
        <source>the state completes at once</source>
        <translation>el estado se completa de inmediato</translation>
    </message>
    <message>
        <source>A wait state runs no GRAFCET.</source>
        <translation>Un estado de espera no ejecuta ningún GRAFCET.</translation>
    </message>
    <message>
        <source>Open GRAFCET</source>
        <translation>Abrir GRAFCET</translation>
    </message>
    <message>
        <source>None (skeleton)</source>
        <translation>Ninguno (esqueleto)</translation>
    </message>
    <message>
        <source>Own GRAFCET</source>
        <translation>GRAFCET propio</translation>
    </message>
    <message>
        <source>Same as %1</source>
        <translation>Igual que %1</translation>
    </message>
    <message>
        <source>Same as mode %1 (no GRAFCET there)</source>
        <translation>Igual que el modo %1 (sin GRAFCET)</translation>
    </message>
    <message>
        <source>%1 is disabled in this mode: nothing runs there.</source>
        <translation>%1 está desactivado en este modo: ahí no se ejecuta nada.</translation>
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
        <translation>Execute reanudado</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <source>Fired</source>
        <translation>Franqueada</translation>
    </message>
    <message>
        <source>Dropped</source>
        <translation>Descartados</translation>
    </message>
</context>
<context>
    <name>editor::PackmlVariablesPanel</name>
    <message>
        <source>Inputs</source>
        <translation>Entradas</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Salidas</translation>
    </message>
</context>
<context>
    <name>editor::ProblemCounter</name>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errores</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n advertencia</numerusform>
            <numerusform>%n advertencias</numerusform>
        </translation>
    </message>
    <message>
        <source>Show the Problems panel</source>
        <translation>Mostrar el panel Problemas</translation>
    </message>
    <message>
        <source>No problems</source>
        <translation>Ningún problema</translation>
    </message>
    <message numerus="yes">
        <source>Verification (outdated): %n finding(s)</source>
        <extracomment>the verification&apos;s findings after the checks&apos; problems in the status bar</extracomment>
        <translation>
            <numerusform>Verificación (desactualizada): %n hallazgo</numerusform>
            <numerusform>Verificación (desactualizada): %n hallazgos</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Verification: %n finding(s)</source>
        <translation>
            <numerusform>Verificación: %n hallazgo</numerusform>
            <numerusform>Verificación: %n hallazgos</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::ProblemsDock</name>
    <message>
        <source>Model</source>
        <translation>Modelo</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Problemas</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Código</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copiar</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>1 error</translation>
    </message>
    <message numerus="yes">
        <source>%n errors</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errores</numerusform>
        </translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 advertencia</translation>
    </message>
    <message numerus="yes">
        <source>%n warnings</source>
        <translation>
            <numerusform>%n advertencia</numerusform>
            <numerusform>%n advertencias</numerusform>
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
        <translation>Mostrar u ocultar los errores</translation>
    </message>
    <message>
        <source>Show or hide the warnings</source>
        <translation>Mostrar u ocultar las advertencias</translation>
    </message>
    <message>
        <source>Show or hide the information messages</source>
        <translation>Mostrar u ocultar los mensajes informativos</translation>
    </message>
    <message>
        <source>Checks (%1)</source>
        <translation>Comprobaciones (%1)</translation>
    </message>
    <message>
        <source>Verification</source>
        <translation>Verificación</translation>
    </message>
    <message>
        <source>Verification (outdated)</source>
        <translation>Verificación (obsoleta)</translation>
    </message>
    <message>
        <source>Verification (%1)</source>
        <translation>Verificación (%1)</translation>
    </message>
    <message>
        <source>%1 step %2</source>
        <extracomment>A step of the nested GRAFCET of a GEMMA step: &quot;F1 step 3&quot;</extracomment>
        <translation>%1 etapa %2</translation>
    </message>
    <message>
        <source>%1 T%2</source>
        <extracomment>A transition of the nested GRAFCET of a GEMMA step: &quot;F1 T2&quot;</extracomment>
        <translation>%1 T%2</translation>
    </message>
    <message>
        <source>%1 GRAFCET</source>
        <extracomment>The row that holds the problems of a GEMMA step&apos;s nested GRAFCET: &quot;F1 GRAFCET&quot;</extracomment>
        <translation>GRAFCET de %1</translation>
    </message>
    <message>
        <source>Nested GRAFCET of %1: 1 problem</source>
        <translation>GRAFCET anidado de %1: 1 problema</translation>
    </message>
    <message numerus="yes">
        <source>Nested GRAFCET of %1: %n problems</source>
        <translation>
            <numerusform>GRAFCET anidado de %1: %n problema</numerusform>
            <numerusform>GRAFCET anidado de %1: %n problemas</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>machine component %1</source>
        <extracomment>A component of the virtual machine: &quot;machine component Clamp&quot;</extracomment>
        <translation>componente de máquina %1</translation>
    </message>
</context>
<context>
    <name>editor::PropertiesPanel</name>
    <message>
        <source>Properties</source>
        <translation>Propiedades</translation>
    </message>
    <message>
        <source>Add Property</source>
        <translation>Añadir propiedad</translation>
    </message>
    <message>
        <source>Add a property after the current one (Insert)</source>
        <translation>Añadir una propiedad tras la actual (Insert)</translation>
    </message>
    <message>
        <source>Remove Property</source>
        <translation>Eliminar propiedad</translation>
    </message>
    <message>
        <source>Remove the current property (Delete)</source>
        <translation>Eliminar la propiedad actual (Supr)</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Subir</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Bajar</translation>
    </message>
    <message>
        <source>&amp;Property:</source>
        <translation>&amp;Propiedad:</translation>
    </message>
    <message>
        <source>never A_Plus AND A_Minus</source>
        <translation>never A_Plus AND A_Minus</translation>
    </message>
    <message>
        <source>Write never P or always P, where P is a condition over the variables that may also use in S (the GEMMA step S is active), S.Xn (step n of S&apos;s nested GRAFCET is active) and a -&gt; b (if a then b). Verify (F7) proves or refutes each one.</source>
        <translation>Escriba never P o always P, donde P es una condición sobre las variables que también puede usar in S (la etapa GEMMA S está activa), S.Xn (la etapa n del GRAFCET anidado de S está activa) y a -&gt; b (si a entonces b). Verificar (F7) demuestra o refuta cada una.</translation>
    </message>
</context>
<context>
    <name>editor::PropertiesTableModel</name>
    <message>
        <source>Property</source>
        <translation>Propiedad</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Comentario</translation>
    </message>
</context>
<context>
    <name>editor::RecentFiles</name>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Abrir &amp;reciente</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>&amp;Vaciar el menú</translation>
    </message>
</context>
<context>
    <name>editor::SimulationDock</name>
    <message>
        <source>fires in the next scan</source>
        <translation>se franquea en el próximo ciclo</translation>
    </message>
    <message>
        <source>condition FALSE</source>
        <translation>condición FALSE</translation>
    </message>
    <message>
        <source>waits for Complete</source>
        <translation>espera a Complete</translation>
    </message>
    <message>
        <source>preempted by %1</source>
        <translation>adelantada por %1</translation>
    </message>
    <message>
        <source>condition unusable (always FALSE)</source>
        <translation>condición inutilizable (siempre FALSE)</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulación</translation>
    </message>
    <message>
        <source>The simulation runs the model scan by scan, as the generated program runs on the PLC: play the inputs, watch the active step and see why each transition fires or not. Editing is locked while it runs.</source>
        <translation>La simulación ejecuta el modelo ciclo a ciclo, como el programa generado se ejecuta en el PLC: actúe sobre las entradas, observe la etapa activa y vea por qué cada transición se franquea o no. La edición queda bloqueada mientras se ejecuta.</translation>
    </message>
    <message>
        <source>Start Simulation</source>
        <translation>Iniciar la simulación</translation>
    </message>
    <message>
        <source>Explanation</source>
        <translation>Explicación</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>Traza</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Escenario</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ejecutar</translation>
    </message>
    <message>
        <source>Run scans at the chosen speed; press again to pause</source>
        <translation>Ejecutar los ciclos a la velocidad elegida; pulse de nuevo para pausar</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <source>Run a single scan</source>
        <translation>Ejecutar un solo ciclo</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Back to the initial step, the inputs to their defaults; clears the trace</source>
        <translation>Vuelve a la etapa inicial y las entradas a su valor inicial; borra la traza</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Terminar</translation>
    </message>
    <message>
        <source>End the simulation and unlock editing</source>
        <translation>Terminar la simulación y desbloquear la edición</translation>
    </message>
    <message>
        <source>&amp;Speed:</source>
        <translation>&amp;Velocidad:</translation>
    </message>
    <message>
        <source> scans/s</source>
        <translation> ciclos/s</translation>
    </message>
    <message>
        <source>Scans per second (the model&apos;s cycle time only sets the simulated time)</source>
        <translation>Ciclos por segundo (el tiempo de ciclo del modelo solo fija el tiempo simulado)</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transición</translation>
    </message>
    <message>
        <source>Next scan</source>
        <translation>Próximo ciclo</translation>
    </message>
    <message>
        <source>&amp;Record as Scenario…</source>
        <translation>&amp;Grabar como escenario…</translation>
    </message>
    <message>
        <source>Re&amp;play Scenario…</source>
        <translation>&amp;Reproducir un escenario…</translation>
    </message>
    <message>
        <source>Run a scenario file from the initial step and check its expectations</source>
        <translation>Ejecutar un archivo de escenario desde la etapa inicial y comprobar sus expectativas</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Entradas</translation>
    </message>
    <message>
        <source>The model declares no variables.</source>
        <translation>El modelo no declara ninguna variable.</translation>
    </message>
    <message>
        <source>Complete of nested steps</source>
        <translation>Complete de las etapas con comportamiento anidado</translation>
    </message>
    <message>
        <source>Automatic: the skeleton function block completes at once. Manual: you play the nested behaviour and set Complete yourself.</source>
        <translation>Automático: el bloque de función esqueleto termina de inmediato. Manual: usted representa el comportamiento anidado y fija Complete.</translation>
    </message>
    <message>
        <source>Switch %1 between TRUE and FALSE</source>
        <translation>Alternar %1 entre TRUE y FALSE</translation>
    </message>
    <message>
        <source>Press</source>
        <translation>Pulsar</translation>
    </message>
    <message>
        <source>TRUE while held down, like a push button (for at least one scan)</source>
        <translation>TRUE mientras se mantiene pulsado, como un pulsador (al menos un ciclo)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automático</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>Manual</translation>
    </message>
    <message>
        <source>How %1&apos;s function block sets Complete</source>
        <translation>Cómo fija Complete el bloque de función de %1</translation>
    </message>
    <message>
        <source>Complete</source>
        <translation>Complete</translation>
    </message>
    <message>
        <source>The value the nested behaviour gives Complete (manual mode)</source>
        <translation>El valor que el comportamiento anidado da a Complete (modo manual)</translation>
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
        <translation>%1.Complete = %2 (tras la última llamada de su bloque de función)</translation>
    </message>
    <message>
        <source>No visible step is active (State = %1).</source>
        <translation>Ninguna etapa visible está activa (State = %1).</translation>
    </message>
    <message>
        <source>Active step: &lt;b&gt;%1&lt;/b&gt; %2 · Entry = %3</source>
        <translation>Etapa activa: &lt;b&gt;%1&lt;/b&gt; %2 · Entry = %3</translation>
    </message>
    <message>
        <source>%1 (family)</source>
        <translation>%1 (familia)</translation>
    </message>
    <message>
        <source>The active step has no transition to evaluate.</source>
        <translation>La etapa activa no tiene ninguna transición que evaluar.</translation>
    </message>
    <message>
        <source>Record this session as a scenario file, or replay one.</source>
        <translation>Grabe esta sesión como archivo de escenario, o reproduzca uno.</translation>
    </message>
    <message>
        <source>%1: every expectation met (%2).</source>
        <translation>%1: se cumplen todas las expectativas (%2).</translation>
    </message>
    <message>
        <source>%1: %2 of %3 expectations failed.</source>
        <translation>%1: %2 de %3 expectativas no se cumplen.</translation>
    </message>
    <message>
        <source>Line %1: %2</source>
        <translation>Línea %1: %2</translation>
    </message>
    <message>
        <source>session</source>
        <translation>sesion</translation>
    </message>
    <message>
        <source>Record as Scenario</source>
        <translation>Grabar como escenario</translation>
    </message>
    <message>
        <source>Simulation scenarios (*.scenario *.txt);;All files (*)</source>
        <translation>Escenarios de simulación (*.scenario *.txt);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>No se ha podido escribir %1.</translation>
    </message>
    <message>
        <source>Recorded %1 scans to %2.</source>
        <translation>%1 ciclos grabados en %2.</translation>
    </message>
    <message>
        <source>Replay Scenario</source>
        <translation>Reproducir un escenario</translation>
    </message>
    <message>
        <source>Could not replay %1.</source>
        <translation>No se ha podido reproducir %1.</translation>
    </message>
    <message>
        <source>upstream step not active</source>
        <translation>etapa anterior no activa</translation>
    </message>
    <message>
        <source>receptivity FALSE</source>
        <translation>receptividad FALSE</translation>
    </message>
    <message>
        <source>receptivity unusable (always FALSE)</source>
        <translation>receptividad inutilizable (siempre FALSE)</translation>
    </message>
    <message>
        <source>not called</source>
        <translation>no llamado</translation>
    </message>
    <message>
        <source>Save this session since the last reset as a scenario file: the inputs of each scan, and expectations for every transition that fired, every output that changed and every nested situation that changed</source>
        <translation>Guardar esta sesión desde el último reinicio como archivo de escenario: las entradas de cada ciclo y expectativas por cada transición franqueada, cada salida que cambió y cada situación de un GRAFCET anidado que cambió</translation>
    </message>
    <message>
        <source>GRAFCET of %1: no step active</source>
        <translation>GRAFCET de %1: ninguna etapa activa</translation>
    </message>
    <message>
        <source>GRAFCET of %1: steps %2</source>
        <translation>GRAFCET de %1: etapas %2</translation>
    </message>
    <message>
        <source>initialised again in the next scan (steps %1)</source>
        <translation>se reinicializa en el próximo ciclo (etapas %1)</translation>
    </message>
    <message>
        <source>first evolution of the next scan</source>
        <translation>primera evolución del próximo ciclo</translation>
    </message>
    <message>
        <source>Until stable: the next scan&apos;s first evolution is explained; later evolutions of the same scan follow with edges FALSE.</source>
        <translation>Hasta estabilidad: se explica la primera evolución del próximo ciclo; las evoluciones siguientes del mismo ciclo siguen con los flancos en FALSE.</translation>
    </message>
    <message>
        <source>One evolution per scan.</source>
        <translation>Una evolución por ciclo.</translation>
    </message>
    <message>
        <source>%1 (step %2): %3 ms of %4 ms</source>
        <extracomment>%1: a timer of a time-dependent receptivity; %2: its step; %3 of %4: elapsed and set time in ms</extracomment>
        <translation>%1 (etapa %2): %3 ms de %4 ms</translation>
    </message>
    <message>
        <source>Outputs: %1</source>
        <extracomment>the outputs a nested GRAFCET drives, with their values (&quot;Spindle = TRUE, Marker = FALSE&quot;)</extracomment>
        <translation>Salidas: %1</translation>
    </message>
    <message>
        <source>T%1 (%2 → %3)</source>
        <extracomment>a transition of a nested GRAFCET: its number, upstream and downstream steps</extracomment>
        <translation>T%1 (%2 → %3)</translation>
    </message>
    <message>
        <source>Outputs and internal variables</source>
        <translation>Salidas y variables internas</translation>
    </message>
    <message>
        <source>Written by the program: %1 is not an input</source>
        <translation>Escrita por el programa: %1 no es una entrada</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Atrás</translation>
    </message>
    <message>
        <source>Show the previous scan of the history (%1); a scan or Run from a past scan continues from it and drops the later scans</source>
        <translation>Mostrar el ciclo anterior del historial (%1); un ciclo o Ejecutar desde un ciclo pasado continúa a partir de él y descarta los ciclos posteriores</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Adelante</translation>
    </message>
    <message>
        <source>Show the next scan of the history (%1)</source>
        <translation>Mostrar el ciclo siguiente del historial (%1)</translation>
    </message>
    <message>
        <source>Scan %1 of %2 (history) · %3 s</source>
        <extracomment>%1 of %2: the past scan shown and the latest scan run; %3: its simulated time in seconds</extracomment>
        <translation>Ciclo %1 de %2 (historial) · %3 s</translation>
    </message>
    <message>
        <source>Replaying %1: scan %2 of %3.</source>
        <extracomment>%1: the scenario file; %2 of %3: the scan reached and the scenario&apos;s last scan</extracomment>
        <translation>Reproduciendo %1: ciclo %2 de %3.</translation>
    </message>
    <message>
        <source>Replay of %1: paused at scan %2 of %3. Press %4 to step, or Run to play the rest.</source>
        <extracomment>%1: the scenario file; %2 of %3: the scan reached and the scenario&apos;s last scan; %4: a key (F10)</extracomment>
        <translation>Reproducción de %1: en pausa en el ciclo %2 de %3. Pulse %4 para avanzar un ciclo, o Ejecutar para reproducir el resto.</translation>
    </message>
    <message>
        <source>Unstable: the GRAFCET of %1 found no stable situation in this scan; its last evolution still fired.</source>
        <extracomment>Unstable is the name of the function block&apos;s output (not translated); %1: macro-steps or enclosing steps</extracomment>
        <translation>Unstable: el GRAFCET de %1 no encontró una situación estable en este ciclo; su última evolución aún franqueó una transición.</translation>
    </message>
    <message>
        <source>the condition of %1</source>
        <translation>la condición de %1</translation>
    </message>
    <message>
        <source>the receptivity of T%1 of %2</source>
        <translation>la receptividad de T%1 de %2</translation>
    </message>
    <message>
        <source>action %1 of step %2 of %3</source>
        <translation>la acción %1 de la etapa %2 de %3</translation>
    </message>
    <message>
        <source>Stopped at scan %1: integer division by zero in %2 (%3 in &apos;%4&apos;). On the PLC the task stops with a fault; Reset to run again.</source>
        <translation>Detenido en el ciclo %1: división entera por cero en %2 (%3 en &apos;%4&apos;). En el PLC la tarea se detiene con un fallo; Reiniciar para volver a ejecutar.</translation>
    </message>
    <message numerus="yes">
        <source>%n other transition(s): an upstream step is not active</source>
        <extracomment>the transitions of a large nested GRAFCET left out of the explanation</extracomment>
        <translation>
            <numerusform>%n transición más: una etapa anterior no está activa</numerusform>
            <numerusform>%n transiciones más: una etapa anterior no está activa</numerusform>
        </translation>
    </message>
    <message>
        <source>Sensors (set by the machine)</source>
        <translation>Sensores (fijados por la máquina)</translation>
    </message>
    <message>
        <source>Written by the machine: %1 is a sensor of %2</source>
        <translation>Escrito por la máquina: %1 es un sensor de %2</translation>
    </message>
    <message>
        <source>It sets the machine&apos;s sensors itself: played in open loop, the machine stands still.</source>
        <translation>Fija él mismo los sensores de la máquina: se reproduce en lazo abierto, la máquina queda parada.</translation>
    </message>
    <message>
        <source>Right-click to inject a fault</source>
        <translation>Clic derecho para inyectar un fallo</translation>
    </message>
</context>
<context>
    <name>editor::SimulationSession</name>
    <message>
        <source>(%1 more)</source>
        <translation>(%1 más)</translation>
    </message>
    <message>
        <source>%1 is a sensor of the machine&apos;s %2: the machine sets it</source>
        <translation>%1 es un sensor de %2 de la máquina: la máquina lo fija</translation>
    </message>
    <message>
        <source>The replay plays the machine&apos;s faults: stop it first</source>
        <translation>La reproducción aplica los fallos de la máquina: deténgala primero</translation>
    </message>
    <message>
        <source>A fault needs the virtual machine running in closed loop</source>
        <translation>Un fallo necesita la máquina virtual en lazo cerrado</translation>
    </message>
</context>
<context>
    <name>editor::StPreviewDock</name>
    <message>
        <source>Structured Text</source>
        <translation>Texto estructurado (ST)</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialecto:</translation>
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
        <translation>Beremiz, OpenPLC, TwinCAT, matiec: variables globales en la configuración</translation>
    </message>
    <message>
        <source>CODESYS V3.5: globals in the list GVL, read as GVL.Name</source>
        <translation>CODESYS V3.5: variables globales en la lista GVL, leídas como GVL.Nombre</translation>
    </message>
    <message>
        <source>The flavour of the generated code; saved with the model</source>
        <translation>La variante del código generado; se guarda con el modelo</translation>
    </message>
    <message>
        <source>%1 is hidden: it generates no code.</source>
        <translation>%1 está oculta: no genera código.</translation>
    </message>
    <message>
        <source>This transition is not effective: it generates no code.</source>
        <translation>Esta transición no es efectiva: no genera código.</translation>
    </message>
    <message>
        <source>%1 generates no function block: only a visible macro-step or enclosing step does.</source>
        <translation>%1 no genera ningún bloque de función: solo lo hace una macroetapa o una etapa encapsulante visible.</translation>
    </message>
    <message>
        <source>%1_FB (the nested GRAFCET of %1)</source>
        <extracomment>the function block shown: &quot;F1_FB (the nested GRAFCET of F1)&quot;</extracomment>
        <translation>%1_FB (el GRAFCET anidado de %1)</translation>
    </message>
    <message>
        <source>No enabled state runs this GRAFCET: it generates no function block.</source>
        <translation>Ningún estado habilitado ejecuta este GRAFCET: no genera ningún bloque de función.</translation>
    </message>
    <message>
        <source>%1 is disabled in this unit mode: the mode&apos;s state machine has no branch for it.</source>
        <translation>%1 está deshabilitado en este modo de unidad: la máquina de estados del modo no tiene rama para él.</translation>
    </message>
</context>
<context>
    <name>editor::StartGuide</name>
    <message>
        <source>Getting started</source>
        <translation>Primeros pasos</translation>
    </message>
    <message>
        <source>&lt;b&gt;Hide&lt;/b&gt; what your machine does not need: select states or transitions and press Delete (Shift+Delete shows them again).</source>
        <translation>&lt;b&gt;Oculte&lt;/b&gt; lo que su máquina no necesita: seleccione estados o transiciones y pulse Supr (Mayús+Supr los vuelve a mostrar).</translation>
    </message>
    <message>
        <source>&lt;b&gt;Declare&lt;/b&gt; the buttons, sensors and actuators in the Variables panel below.</source>
        <translation>&lt;b&gt;Declare&lt;/b&gt; los pulsadores, sensores y actuadores en el panel Variables de abajo.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Write&lt;/b&gt; each transition&apos;s condition: select the transition and press Enter. Red marks what is not finished yet.</source>
        <translation>&lt;b&gt;Escriba&lt;/b&gt; la condición de cada transición: seleccione la transición y pulse Intro. En rojo, lo que aún no está terminado.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Simulate&lt;/b&gt; with F5, &lt;b&gt;verify&lt;/b&gt; with F7, then export PLCopen XML for your PLC.</source>
        <translation>&lt;b&gt;Simule&lt;/b&gt; con F5, &lt;b&gt;verifique&lt;/b&gt; con F7 y exporte PLCopen XML para su PLC.</translation>
    </message>
    <message>
        <source>The chart is the GEMMA sheet: the ways your machine stops (A), works (F) and fails (D), and the transitions between them.</source>
        <translation>El diagrama es la hoja GEMMA: cómo se para (A), funciona (F) y falla (D) su máquina, y las transiciones entre ellos.</translation>
    </message>
    <message>
        <source>Select a step or a transition to edit it here.</source>
        <translation>Seleccione una etapa o una transición para editarla aquí.</translation>
    </message>
    <message>
        <source>Open an Example</source>
        <translation>Abrir un ejemplo</translation>
    </message>
    <message>
        <source>A finished model to look at and simulate, opened as an untitled copy</source>
        <translation>Un modelo terminado para ver y simular, abierto como copia sin título</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>Guía del usuario</translation>
    </message>
    <message>
        <source>How to build a model step by step (F1)</source>
        <translation>Cómo construir un modelo paso a paso (F1)</translation>
    </message>
</context>
<context>
    <name>editor::StepDock</name>
    <message>
        <source>Step</source>
        <translation>Etapa</translation>
    </message>
    <message>
        <source>Select a step in the chart to see and edit its properties.</source>
        <translation>Seleccione una etapa en el diagrama para ver y editar sus propiedades.</translation>
    </message>
    <message>
        <source>Simple step: no nested behaviour.
Macro-step: its transitions wait until the nested behaviour is complete.
Enclosing step: its transitions fire whatever the nested behaviour is doing.</source>
        <translation>Etapa simple: sin comportamiento anidado.
Macroetapa: sus transiciones esperan a que el comportamiento anidado haya terminado.
Etapa encapsulante: sus transiciones se franquean haga lo que haga el comportamiento anidado.</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Tipo:</translation>
    </message>
    <message>
        <source>&amp;Initial</source>
        <translation>&amp;Inicial</translation>
    </message>
    <message>
        <source>&amp;Hidden</source>
        <translation>Ocu&amp;lta</translation>
    </message>
    <message>
        <source>A hidden step is not part of this machine: it generates no code, and its transitions are not effective.</source>
        <translation>Una etapa oculta no forma parte de esta máquina: no genera código y sus transiciones no son efectivas.</translation>
    </message>
    <message>
        <source>What this state does on this machine</source>
        <translation>Lo que hace este estado en esta máquina</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Comentario:</translation>
    </message>
    <message>
        <source>Incoming transitions</source>
        <translation>Transiciones de entrada</translation>
    </message>
    <message>
        <source>Outgoing transitions, by priority</source>
        <translation>Transiciones de salida, por prioridad</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transición</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Condición</translation>
    </message>
    <message>
        <source>Click a transition to select it</source>
        <translation>Haga clic en una transición para seleccionarla</translation>
    </message>
    <message>
        <source>%1 · state number %2</source>
        <translation>%1 · estado número %2</translation>
    </message>
    <message>
        <source>%1 is the initial step. There is always exactly one initial step: to change it, make another step initial.</source>
        <translation>%1 es la etapa inicial. Siempre hay exactamente una etapa inicial: para cambiarla, haga inicial otra etapa.</translation>
    </message>
    <message>
        <source>Make %1 the initial step (the PLC starts in it). The current initial step is %2.</source>
        <translation>Hacer de %1 la etapa inicial (el PLC arranca en ella). La etapa inicial actual es %2.</translation>
    </message>
    <message>
        <source>F (family) →</source>
        <extracomment>an incoming transition: its source, an arrow</extracomment>
        <translation>F (familia) →</translation>
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
        <translation>Transición de familia: se evalúa antes que las transiciones propias de cada estado F visible.</translation>
    </message>
    <message>
        <source>Negated</source>
        <translation>Negada</translation>
    </message>
    <message>
        <source>Condition: %1</source>
        <translation>Condición: %1</translation>
    </message>
    <message>
        <source>Not effective (%1): generates no code.</source>
        <translation>No efectiva (%1): no genera código.</translation>
    </message>
    <message>
        <source>%1 (negated)</source>
        <extracomment>a negated transition in the Step dock&apos;s lists: the entry, then the mark</extracomment>
        <translation>%1 (negada)</translation>
    </message>
    <message>
        <source>Open Nested GRAFCET</source>
        <translation>Abrir el GRAFCET anidado</translation>
    </message>
    <message>
        <source>Show the nested GRAFCET of this step in a tab beside the GEMMA chart (double-click the step on the chart does the same)</source>
        <translation>Mostrar el GRAFCET anidado de esta etapa en una pestaña junto al diagrama GEMMA (un doble clic en la etapa del diagrama hace lo mismo)</translation>
    </message>
</context>
<context>
    <name>editor::StepItem</name>
    <message>
        <source>Simple step</source>
        <translation>Etapa simple</translation>
    </message>
    <message>
        <source>Macro-step</source>
        <translation>Macroetapa</translation>
    </message>
    <message>
        <source>Enclosing step</source>
        <translation>Etapa encapsulante</translation>
    </message>
    <message>
        <source>%1, initial</source>
        <translation>%1, inicial</translation>
    </message>
    <message>
        <source>%1, hidden</source>
        <translation>%1, oculta</translation>
    </message>
    <message numerus="yes">
        <source>Has a nested GRAFCET (%n steps)</source>
        <translation>
            <numerusform>Tiene un GRAFCET anidado (%n etapa)</numerusform>
            <numerusform>Tiene un GRAFCET anidado (%n etapas)</numerusform>
        </translation>
    </message>
    <message>
        <source>Its GRAFCET runs: steps %1 active</source>
        <extracomment>simulation; %1: the active steps of the nested GRAFCET (&quot;3, 5&quot;)</extracomment>
        <translation>Su GRAFCET evoluciona: etapas %1 activas</translation>
    </message>
    <message>
        <source>Its nested GRAFCET has 1 problem</source>
        <translation>Su GRAFCET anidado tiene 1 problema</translation>
    </message>
    <message numerus="yes">
        <source>Its nested GRAFCET has %n problems</source>
        <translation>
            <numerusform>Su GRAFCET anidado tiene %n problema</numerusform>
            <numerusform>Su GRAFCET anidado tiene %n problemas</numerusform>
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
        <translation>Etapa</translation>
    </message>
    <message>
        <source>Fired</source>
        <translation>Franqueada</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Entry</translation>
    </message>
    <message>
        <source>Tokens TRUE</source>
        <translation>Memorias TRUE</translation>
    </message>
    <message>
        <source>Changed inputs</source>
        <translation>Entradas cambiadas</translation>
    </message>
</context>
<context>
    <name>editor::TransitionDock</name>
    <message>
        <source>Transition</source>
        <translation>Transición</translation>
    </message>
    <message>
        <source>Select a transition in the chart to see and edit its condition.</source>
        <translation>Seleccione una transición en el diagrama para ver y editar su condición.</translation>
    </message>
    <message>
        <source>Click a step to select it</source>
        <translation>Haga clic en una etapa para seleccionarla</translation>
    </message>
    <message>
        <source>C&amp;ondition:</source>
        <translation>C&amp;ondición:</translation>
    </message>
    <message>
        <source>e.g. Start AND NOT Stop</source>
        <translation>p. ej. Start AND NOT Stop</translation>
    </message>
    <message>
        <source>Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND (&amp;), XOR, OR, comparisons and arithmetic.
Ctrl+Space completes a variable name.</source>
        <translation>Texto estructurado (ST): variables declaradas, números, TRUE, FALSE, NOT, AND (&amp;), XOR, OR, comparaciones y aritmética.
Ctrl+Espacio completa un nombre de variable.</translation>
    </message>
    <message>
        <source>&amp;Priority:</source>
        <translation>&amp;Prioridad:</translation>
    </message>
    <message>
        <source>&amp;Negated</source>
        <translation>&amp;Negada</translation>
    </message>
    <message>
        <source>Negation flips when this transition waits for the nested behaviour of its source:
a negated transition out of a macro-step ignores Complete;
a negated transition out of an enclosing step waits for Complete.</source>
        <translation>La negación invierte la espera de esta transición al comportamiento anidado de su origen:
una transición negada que sale de una macroetapa ignora Complete;
una transición negada que sale de una etapa encapsulante espera a Complete.</translation>
    </message>
    <message>
        <source>&amp;Hidden</source>
        <translation>Ocu&amp;lta</translation>
    </message>
    <message>
        <source>A hidden transition is not part of this machine: it generates no code.</source>
        <translation>Una transición oculta no forma parte de esta máquina: no genera código.</translation>
    </message>
    <message>
        <source>Tokens</source>
        <translation>Memorias</translation>
    </message>
    <message>
        <source>F (family)</source>
        <translation>F (familia)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <extracomment>a transition: source step, arrow, target step</extracomment>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Not effective (%1): generates no code.</source>
        <translation>No efectiva (%1): no genera código.</translation>
    </message>
    <message>
        <source>First</source>
        <translation>Primera</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Ninguna</translation>
    </message>
    <message>
        <source>The family transition is evaluated before the own transitions of every visible F state.</source>
        <translation>La transición de familia se evalúa antes que las transiciones propias de cada estado F visible.</translation>
    </message>
    <message>
        <source>Only effective transitions have a priority: show this transition and both its steps first.</source>
        <translation>Solo las transiciones efectivas tienen prioridad: muestre primero esta transición y sus dos etapas.</translation>
    </message>
    <message>
        <source> of %1</source>
        <extracomment>after the priority in its spin box: &quot;2 of 5&quot;</extracomment>
        <translation> de %1</translation>
    </message>
    <message>
        <source>1 is evaluated first among the effective transitions out of %1; the others move to make room.</source>
        <translation>1 se evalúa primero entre las transiciones efectivas que salen de %1; las demás se desplazan para dejar sitio.</translation>
    </message>
    <message>
        <source>Negation has no effect here: family transitions never wait for Complete.</source>
        <translation>La negación no tiene efecto aquí: las transiciones de familia nunca esperan a Complete.</translation>
    </message>
    <message>
        <source>Negation has no effect here: %1 is a simple step, and only transitions out of macro-steps and enclosing steps wait for Complete.</source>
        <translation>La negación no tiene efecto aquí: %1 es una etapa simple, y solo las transiciones que salen de macroetapas y etapas encapsulantes esperan a Complete.</translation>
    </message>
    <message>
        <source>Fires without waiting for the nested behaviour of macro-step %1 to complete.</source>
        <translation>Se franquea sin esperar a que termine el comportamiento anidado de la macroetapa %1.</translation>
    </message>
    <message>
        <source>Waits until the nested behaviour of macro-step %1 is complete (%1.Complete). Negate it to fire at once.</source>
        <translation>Espera a que termine el comportamiento anidado de la macroetapa %1 (%1.Complete). Niéguela para franquearla de inmediato.</translation>
    </message>
    <message>
        <source>Waits until the nested behaviour of enclosing step %1 is complete (%1.Complete).</source>
        <translation>Espera a que termine el comportamiento anidado de la etapa encapsulante %1 (%1.Complete).</translation>
    </message>
    <message>
        <source>Fires whatever the nested behaviour of enclosing step %1 is doing. Negate it to wait for %1.Complete.</source>
        <translation>Se franquea haga lo que haga el comportamiento anidado de la etapa encapsulante %1. Niéguela para esperar a %1.Complete.</translation>
    </message>
    <message>
        <source>Token on %1 (compared: no polarity)</source>
        <translation>Memoria de %1 (comparada: sin polaridad)</translation>
    </message>
    <message>
        <source>Token on %1 (both NO and NC)</source>
        <translation>Memoria de %1 (NA y NC a la vez)</translation>
    </message>
    <message>
        <source>Token on %1 (NC)</source>
        <translation>Memoria de %1 (NC)</translation>
    </message>
    <message>
        <source>Token on %1 (NO)</source>
        <translation>Memoria de %1 (NA)</translation>
    </message>
    <message>
        <source>A token replaces a literal %1 or NOT %1: rewrite the condition so that %1 has one polarity.</source>
        <translation>Una memoria sustituye a un literal %1 o NOT %1: reescriba la condición para que %1 tenga una sola polaridad.</translation>
    </message>
    <message>
        <source>Normally closed: remembers that %1 was FALSE while the nested behaviour of %2 was not complete.</source>
        <translation>Normalmente cerrada: recuerda que %1 estuvo a FALSE mientras el comportamiento anidado de %2 no había terminado.</translation>
    </message>
    <message>
        <source>Normally open: remembers that %1 was TRUE while the nested behaviour of %2 was not complete.</source>
        <translation>Normalmente abierta: recuerda que %1 estuvo a TRUE mientras el comportamiento anidado de %2 no había terminado.</translation>
    </message>
    <message>
        <source>Generated as %1_%2_%3_MEM.</source>
        <translation>Se genera como %1_%2_%3_MEM.</translation>
    </message>
    <message>
        <source>Token on %1 (not a BOOL variable of the condition)</source>
        <translation>Memoria de %1 (no es una variable BOOL de la condición)</translation>
    </message>
    <message>
        <source>Uncheck to remove this token.</source>
        <translation>Desmarque para quitar esta memoria.</translation>
    </message>
    <message>
        <source>Family transitions never wait for Complete, so tokens do not apply to them.</source>
        <translation>Las transiciones de familia nunca esperan a Complete, así que las memorias no se les aplican.</translation>
    </message>
    <message>
        <source>Tokens apply to transitions out of macro-steps and enclosing steps; %1 is a simple step.</source>
        <translation>Las memorias se aplican a las transiciones que salen de macroetapas y etapas encapsulantes; %1 es una etapa simple.</translation>
    </message>
    <message>
        <source>Correct the condition to choose its tokens.</source>
        <translation>Corrija la condición para elegir sus memorias.</translation>
    </message>
    <message>
        <source>The condition uses no BOOL variable.</source>
        <translation>La condición no usa ninguna variable BOOL.</translation>
    </message>
    <message>
        <source>A token keeps a short pulse of a BOOL variable that occurs while the nested behaviour of %1 is not yet complete.</source>
        <translation>Una memoria retiene un pulso breve de una variable BOOL que se produce mientras el comportamiento anidado de %1 aún no ha terminado.</translation>
    </message>
</context>
<context>
    <name>editor::TransitionItem</name>
    <message>
        <source>Family transition: applies to every F state</source>
        <translation>Transición de familia: se aplica a cada estado F</translation>
    </message>
    <message>
        <source>Priority %1</source>
        <translation>Prioridad %1</translation>
    </message>
    <message>
        <source>Not effective (hidden)</source>
        <translation>No efectiva (oculta)</translation>
    </message>
    <message>
        <source>%1, negated</source>
        <translation>%1, negada</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Condición:</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>vacía</translation>
    </message>
    <message>
        <source>Tokens: %1</source>
        <translation>Memorias: %1</translation>
    </message>
</context>
<context>
    <name>editor::UserGuide</name>
    <message>
        <source>GG Studio User Guide</source>
        <translation>Guía del usuario de GG Studio</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Atrás</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Adelante</translation>
    </message>
    <message>
        <source>Getting Started</source>
        <translation>Primeros pasos</translation>
    </message>
</context>
<context>
    <name>editor::VariablesDock</name>
    <message>
        <source>Variables</source>
        <translation>Variables</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filtrar</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Añadir</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplicar</translation>
    </message>
    <message>
        <source>Duplicate the selected variables</source>
        <translation>Duplicar las variables seleccionadas</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Subir</translation>
    </message>
    <message>
        <source>Move the current variable up (declaration order)</source>
        <translation>Subir la variable actual (orden de declaración)</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Bajar</translation>
    </message>
    <message>
        <source>Move the current variable down (declaration order)</source>
        <translation>Bajar la variable actual (orden de declaración)</translation>
    </message>
    <message>
        <source>Sort by Name</source>
        <translation>Ordenar por nombre</translation>
    </message>
    <message>
        <source>Sort the declarations by name (one undo step)</source>
        <translation>Ordenar las declaraciones por nombre (un solo paso de deshacer)</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Copiar</translation>
    </message>
    <message>
        <source>Paste</source>
        <translation>Pegar</translation>
    </message>
    <message>
        <source>Variable%1</source>
        <translation>Variable%1</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n variables</source>
        <translation>
            <numerusform>Eliminar %n variable</numerusform>
            <numerusform>Eliminar %n variables</numerusform>
        </translation>
    </message>
    <message>
        <source>Sort variables by name</source>
        <translation>Ordenar las variables por nombre</translation>
    </message>
    <message>
        <source>Remove the selected variables</source>
        <translation>Eliminar las variables seleccionadas</translation>
    </message>
    <message>
        <source>Copy the selected variables as tab-separated rows</source>
        <translation>Copiar las variables seleccionadas como filas separadas por tabuladores</translation>
    </message>
    <message>
        <source>Show only the variables whose name, type, kind, default or comment contains this text</source>
        <translation>Mostrar solo las variables cuyo nombre, tipo, clase, valor inicial o comentario contiene este texto</translation>
    </message>
    <message>
        <source>Add a BOOL variable after the current one (Insert)</source>
        <translation>Añadir una variable BOOL después de la actual (Insert)</translation>
    </message>
    <message>
        <source>Paste rows from a spreadsheet: name, type, default, comment and kind, in this order or in the order a first row of column titles gives</source>
        <translation>Pegar filas de una hoja de cálculo: nombre, tipo, valor inicial, comentario y clase, en este orden o en el que indique una primera fila de títulos de columna</translation>
    </message>
</context>
<context>
    <name>editor::VariablesTableModel</name>
    <message>
        <source>No default: the PLC starts with %1.</source>
        <translation>Sin valor inicial: el PLC arranca con %1.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a supported type: use one of %2.</source>
        <translation>&apos;%1&apos; no es un tipo admitido: use uno de estos: %2.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Valor inicial</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Comentario</translation>
    </message>
    <message>
        <source>IEC 61131-3 identifier, unique ignoring case. Renaming updates every condition.</source>
        <translation>Identificador IEC 61131-3, único sin distinguir mayúsculas y minúsculas. Al renombrarlo se actualizan todas las condiciones.</translation>
    </message>
    <message>
        <source>Elementary IEC 61131-3 type</source>
        <translation>Tipo elemental IEC 61131-3</translation>
    </message>
    <message>
        <source>Initial value, a literal of the type; empty for the type&apos;s implicit default</source>
        <translation>Valor inicial, un literal del tipo; vacío para el valor por defecto implícito del tipo</translation>
    </message>
    <message>
        <source>Free text, written into the generated declarations</source>
        <translation>Texto libre, que se escribe en las declaraciones generadas</translation>
    </message>
    <message>
        <source>Line %1: the name is empty.</source>
        <translation>Línea %1: el nombre está vacío.</translation>
    </message>
    <message>
        <source>Line %1: &apos;%2&apos; is not a supported type: use one of %3.</source>
        <translation>Línea %1: &apos;%2&apos; no es un tipo admitido: use uno de estos: %3.</translation>
    </message>
    <message>
        <source>There are no variables to paste: copy rows of name, type, default and comment, separated by tabs.</source>
        <translation>No hay variables que pegar: copie filas de nombre, tipo, valor inicial y comentario, separados por tabuladores.</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Salida</translation>
    </message>
    <message>
        <source>Internal</source>
        <translation>Interna</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Entrada</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a kind: use %2, %3 or %4.</source>
        <translation>&apos;%1&apos; no es una clase: use %2, %3 o %4.</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Clase</translation>
    </message>
    <message>
        <source>Input: read from the machine. Output: written by the actions of nested GRAFCETs. Internal: a memory the program writes and reads.</source>
        <translation>Entrada: leída de la máquina. Salida: escrita por las acciones de los GRAFCET anidados. Interna: una memoria que el programa escribe y lee.</translation>
    </message>
    <message>
        <source>Line %1: &apos;%2&apos; is not a kind: use input, output or internal.</source>
        <translation>Línea %1: &apos;%2&apos; no es una clase: use entrada, salida o interna.</translation>
    </message>
</context>
<context>
    <name>editor::VerificationPanel</name>
    <message>
        <source>&amp;Verify</source>
        <translation>&amp;Verificar</translation>
    </message>
    <message>
        <source>&amp;Show on Chart</source>
        <translation>&amp;Mostrar en el diagrama</translation>
    </message>
    <message>
        <source>&amp;Replay in Simulator</source>
        <translation>&amp;Reproducir en el simulador</translation>
    </message>
    <message>
        <source>Explore every input sequence of the GEMMA layer and report what cannot happen</source>
        <translation>Explorar todas las secuencias de entradas de la capa GEMMA e indicar lo que no puede ocurrir</translation>
    </message>
    <message>
        <source>Select the element of the finding on the chart</source>
        <translation>Seleccionar el elemento del resultado en el diagrama</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Código</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <source>Scans</source>
        <translation>Ciclos</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Mensaje</translation>
    </message>
    <message>
        <source>Scans of the counterexample, which the simulator can replay</source>
        <translation>Ciclos del contraejemplo, que el simulador puede reproducir</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copiar</translation>
    </message>
    <message>
        <source>Verifying…</source>
        <translation>Verificando…</translation>
    </message>
    <message>
        <source>Verification failed: %1.</source>
        <translation>La verificación ha fallado: %1.</translation>
    </message>
    <message>
        <source>Not verified yet.</source>
        <translation>Aún no verificado.</translation>
    </message>
    <message>
        <source>Model changed since verification: verify again to update the findings.</source>
        <translation>El modelo ha cambiado desde la verificación: vuelva a verificar para actualizar los resultados.</translation>
    </message>
    <message>
        <source>Some properties do not hold (%1 configurations explored).</source>
        <translation>Algunas propiedades no se cumplen (%1 configuraciones exploradas).</translation>
    </message>
    <message>
        <source>Every property holds; see the notes (%1 configurations explored).</source>
        <translation>Se cumplen todas las propiedades; vea las notas (%1 configuraciones exploradas).</translation>
    </message>
    <message>
        <source>Every property holds (%1 configurations explored).</source>
        <translation>Se cumplen todas las propiedades (%1 configuraciones exploradas).</translation>
    </message>
    <message>
        <source>The model changed since verification: verify again to replay</source>
        <translation>El modelo ha cambiado desde la verificación: vuelva a verificar para reproducir</translation>
    </message>
    <message>
        <source>Start the simulation and replay the scans that lead to the finding</source>
        <translation>Iniciar la simulación y reproducir los ciclos que llevan al resultado</translation>
    </message>
    <message>
        <source>Complete settings changed since verification: verify again to update the findings.</source>
        <translation>Los ajustes de Complete han cambiado desde la verificación: vuelva a verificar para actualizar los resultados.</translation>
    </message>
    <message>
        <source>All Complete outputs free</source>
        <translation>Todas las salidas Complete libres</translation>
    </message>
    <message>
        <source>Assumed Complete automatic: %1</source>
        <translation>Complete supuesto automático: %1</translation>
    </message>
    <message>
        <source>Free: the nested behaviour may complete at any scan, or never. Automatic: Complete is TRUE at every scan, as the skeleton function block. Verify assumes automatic the nested steps whose Complete is Automatic in the Simulation dock while the simulation runs; all others are free.</source>
        <translation>Libre: el comportamiento anidado puede terminar en cualquier ciclo, o nunca. Automático: Complete es TRUE en cada ciclo, como en el bloque de función esqueleto. La verificación supone automáticas las etapas anidadas cuyo Complete está en Automático en el panel Simulación mientras la simulación está activa; todas las demás son libres.</translation>
    </message>
    <message>
        <source>%1: T%2</source>
        <translation>%1: T%2</translation>
    </message>
    <message>
        <source>%1: step %2</source>
        <extracomment>A step of a nested GRAFCET: %1 the GEMMA step, %2 its number</extracomment>
        <translation>%1: etapa %2</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modelo</translation>
    </message>
    <message>
        <source>%1: nested GRAFCET</source>
        <extracomment>The row that groups the findings about the nested GRAFCET of a GEMMA step, e.g. &quot;F1 Normal production&quot;</extracomment>
        <translation>%1: GRAFCET anidado</translation>
    </message>
    <message>
        <source>The findings about the nested GRAFCET of %1</source>
        <translation>Los hallazgos sobre el GRAFCET anidado de %1</translation>
    </message>
    <message>
        <source>Some properties do not hold (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Algunas propiedades no se cumplen (%1 configuraciones del nivel GEMMA y %2 estados del programa de los dos niveles explorados).</translation>
    </message>
    <message>
        <source>Every property holds; see the notes (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Todas las propiedades se cumplen; vea las notas (%1 configuraciones del nivel GEMMA y %2 estados del programa de los dos niveles explorados).</translation>
    </message>
    <message>
        <source>Every property holds (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Todas las propiedades se cumplen (%1 configuraciones del nivel GEMMA y %2 estados del programa de los dos niveles explorados).</translation>
    </message>
    <message>
        <source>The exploration of both layers abstracted:</source>
        <translation>La exploración de los dos niveles abstrajo:</translation>
    </message>
    <message>
        <source>Exact time switched on since verification: verify again to update the findings.</source>
        <translation>Tiempo exacto activado desde la verificación: vuelva a verificar para actualizar los resultados.</translation>
    </message>
    <message>
        <source>Exact time switched off since verification: verify again to update the findings.</source>
        <translation>Tiempo exacto desactivado desde la verificación: vuelva a verificar para actualizar los resultados.</translation>
    </message>
    <message>
        <source>Exact time</source>
        <translation>Tiempo exacto</translation>
    </message>
    <message>
        <source>Exact time: every timer elapses exactly when the PLC&apos;s would, counted in scans (Simulation &gt; Verify with Exact Time).</source>
        <translation>Tiempo exacto: cada temporizador vence exactamente cuando lo haría el del PLC, contado en ciclos (Simulación &gt; Verificar con tiempo exacto).</translation>
    </message>
    <message>
        <source>Nothing is violated, but some properties are undecided: see the findings (%1 configurations explored).</source>
        <translation>Nada se incumple, pero algunas propiedades están sin decidir: vea los resultados (%1 configuraciones exploradas).</translation>
    </message>
    <message>
        <source>Nothing is violated, but some properties are undecided: see the findings (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Nada se incumple, pero algunas propiedades están sin decidir: vea los resultados (%1 configuraciones del nivel GEMMA y %2 estados del programa de los dos niveles explorados).</translation>
    </message>
    <message>
        <source>&amp;Time limit:</source>
        <translation>&amp;Límite de tiempo:</translation>
    </message>
    <message>
        <source> s</source>
        <extracomment>The unit after the verification&apos;s time limit: &quot;4 s&quot;</extracomment>
        <translation> s</translation>
    </message>
    <message>
        <source>How long a verification may run. Past it, what is not decided yet is reported as undecided (GV100) with how far the exploration got: give more time and verify again.</source>
        <translation>Cuánto puede durar una verificación. Pasado ese tiempo, lo que aún no está decidido se indica como sin decidir (GV100), con hasta dónde llegó la exploración: dé más tiempo y vuelva a verificar.</translation>
    </message>
    <message>
        <source>The machine is used since verification: verify again to update the findings.</source>
        <translation>La máquina se usa desde la verificación: verifique de nuevo para actualizar los hallazgos.</translation>
    </message>
    <message>
        <source>The machine is no longer used since verification: verify again to update the findings.</source>
        <translation>La máquina ya no se usa desde la verificación: verifique de nuevo para actualizar los hallazgos.</translation>
    </message>
    <message>
        <source>With the machine</source>
        <translation>Con la máquina</translation>
    </message>
    <message>
        <source>With the machine: the sensors the model&apos;s machine drives follow it, scan by scan, instead of taking any value (Simulation &gt; Verify with the Machine).</source>
        <translation>Con la máquina: los sensores que mueve la máquina del modelo la siguen, ciclo a ciclo, en lugar de tomar cualquier valor (Simulación &gt; Verificar con la máquina).</translation>
    </message>
    <message>
        <source>Single faults switched on since verification: verify again to update the findings.</source>
        <translation>Fallos únicos activados desde la verificación: verifique de nuevo para actualizar los hallazgos.</translation>
    </message>
    <message>
        <source>Single faults switched off since verification: verify again to update the findings.</source>
        <translation>Fallos únicos desactivados desde la verificación: verifique de nuevo para actualizar los hallazgos.</translation>
    </message>
    <message>
        <source>Single faults</source>
        <translation>Fallos únicos</translation>
    </message>
    <message>
        <source>Single faults: any one sensor stuck or flickering, or one cylinder or conveyor jammed, from any scan on (Simulation &gt; Verify with Single Faults).</source>
        <translation>Fallos únicos: un sensor cualquiera bloqueado o intermitente, o un cilindro o una cinta atascados, a partir de cualquier ciclo (Simulación &gt; Verificar con fallos únicos).</translation>
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
        <translation>El zoom de la pestaña en primer plano. Ctrl+rueda o un gesto de pellizco hace zoom alrededor del ratón; Ctrl+0 ajusta el dibujo a la ventana, Ctrl+1 lo muestra a su tamaño real</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Editor for the GEMMA-GRAFCET method of specifying machine operating modes</source>
        <translation>Editor para el método GEMMA-GRAFCET de especificación de los modos de marcha y parada de las máquinas</translation>
    </message>
    <message>
        <source>The model file to open (GG Studio JSON, GG-Generator JSON or GG Studio PLCopen XML).</source>
        <translation>El archivo de modelo que se abrirá (JSON de GG Studio, JSON de GG-Generator o PLCopen XML de GG Studio).</translation>
    </message>
</context>
<context>
    <name>modbus::ModbusLink</name>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation>no se puede escuchar en %1:%2: %3</translation>
    </message>
    <message>
        <source>cannot connect to %1:%2: %3</source>
        <translation>no se puede conectar a %1:%2: %3</translation>
    </message>
    <message>
        <source>write of %1 %2..%3 to %4:%5</source>
        <translation>escritura de %1 %2..%3 en %4:%5</translation>
    </message>
    <message>
        <source>read of %1 %2..%3 from %4:%5</source>
        <translation>lectura de %1 %2..%3 desde %4:%5</translation>
    </message>
</context>
</TS>
