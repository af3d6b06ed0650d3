<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>AddGrafcetActionCommand</name>
    <message>
        <source>Add action %1 to %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Ajouter l’action %1 à l’étape %3 de %2</translation>
    </message>
</context>
<context>
    <name>AddMachineComponentCommand</name>
    <message>
        <source>Add %1 %2</source>
        <extracomment>%1: a kind of machine component (&quot;Conveyor&quot;); %2: its name</extracomment>
        <translation>Ajouter %1 %2</translation>
    </message>
</context>
<context>
    <name>AddModeCommand</name>
    <message>
        <source>Add mode %1 %2</source>
        <translation>Ajouter le mode %1 %2</translation>
    </message>
</context>
<context>
    <name>AddPropertyCommand</name>
    <message>
        <source>Add property</source>
        <translation>Ajouter une propriété</translation>
    </message>
</context>
<context>
    <name>AddVariableCommand</name>
    <message>
        <source>Add variable %1</source>
        <translation>Ajouter la variable %1</translation>
    </message>
</context>
<context>
    <name>ChartExport</name>
    <message>
        <source>GEMMA-GRAFCET chart drawn by GG Studio</source>
        <translation>Diagramme GEMMA-GRAFCET dessiné par GG Studio</translation>
    </message>
</context>
<context>
    <name>ConditionErrorText</name>
    <message>
        <source>comments are not allowed in a condition</source>
        <translation>les commentaires ne sont pas autorisés dans une réceptivité</translation>
    </message>
    <message>
        <source>use = to compare; := is assignment</source>
        <translation>utilisez = pour comparer&#xa0;; := est l&apos;affectation</translation>
    </message>
    <message>
        <source>use = to compare; == is not Structured Text</source>
        <translation>utilisez = pour comparer&#xa0;; == n&apos;existe pas en Structured Text</translation>
    </message>
    <message>
        <source>use &lt;&gt; for &apos;not equal&apos;</source>
        <translation>utilisez &lt;&gt; pour &apos;différent de&apos;</translation>
    </message>
    <message>
        <source>use NOT for negation</source>
        <translation>utilisez NOT pour la négation</translation>
    </message>
    <message>
        <source>use AND (or &amp;) for &apos;and&apos;</source>
        <translation>utilisez AND (ou &amp;) pour &apos;et&apos;</translation>
    </message>
    <message>
        <source>use OR for &apos;or&apos;</source>
        <translation>utilisez OR pour &apos;ou&apos;</translation>
    </message>
    <message>
        <source>&apos;**&apos; (power) is not supported in a condition</source>
        <translation>&apos;**&apos; (puissance) n&apos;est pas pris en charge dans une réceptivité</translation>
    </message>
    <message>
        <source>&apos;;&apos; is not allowed in a condition: write only the expression</source>
        <translation>&apos;;&apos; n&apos;est pas autorisé dans une réceptivité&#xa0;: écrivez seulement l&apos;expression</translation>
    </message>
    <message>
        <source>the text contains bytes that are not valid UTF-8</source>
        <translation>le texte contient des octets qui ne sont pas de l&apos;UTF-8 valide</translation>
    </message>
    <message>
        <source>&apos;%1&apos; contains a non-ASCII character: names use ASCII letters, digits and _ only</source>
        <translation>&apos;%1&apos; contient un caractère non ASCII&#xa0;: les noms n&apos;utilisent que des lettres ASCII, des chiffres et _</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not supported: write plain decimal numbers, TRUE or FALSE (no typed, based or time literals)</source>
        <translation>&apos;%1&apos; n&apos;est pas pris en charge&#xa0;: écrivez des nombres décimaux simples, TRUE ou FALSE (pas de littéraux typés, en base ou de durée)</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: qualified names are not allowed, write the variable name alone</source>
        <translation>&apos;%1&apos;&#xa0;: les noms qualifiés ne sont pas autorisés, écrivez le nom de la variable seul</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid number</source>
        <translation>&apos;%1&apos; n&apos;est pas un nombre valide</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: write only the boolean expression, without IF ... THEN</source>
        <extracomment>%1: IF, THEN, ELSE... as written</extracomment>
        <translation>&apos;%1&apos; n&apos;est pas autorisé dans une réceptivité&#xa0;: écrivez seulement l&apos;expression booléenne, sans IF ... THEN</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: it is a type name</source>
        <translation>&apos;%1&apos; n&apos;est pas autorisé dans une réceptivité&#xa0;: c&apos;est un nom de type</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed in a condition: it is an IEC 61131-3 keyword</source>
        <translation>&apos;%1&apos; n&apos;est pas autorisé dans une réceptivité&#xa0;: c&apos;est un mot-clé IEC 61131-3</translation>
    </message>
    <message>
        <source>unexpected control character (byte %1)</source>
        <extracomment>%1: the byte in hexadecimal (0x1B)</extracomment>
        <translation>caractère de contrôle inattendu (octet %1)</translation>
    </message>
    <message>
        <source>unexpected character &apos;%1&apos;</source>
        <translation>caractère &apos;%1&apos; inattendu</translation>
    </message>
    <message>
        <source>condition too complex: operators nested more than %1 levels deep</source>
        <translation>réceptivité trop complexe&#xa0;: opérateurs imbriqués sur plus de %1 niveaux</translation>
    </message>
    <message>
        <source>condition nested too deeply: more than %1 levels of parentheses</source>
        <translation>réceptivité trop imbriquée&#xa0;: plus de %1 niveaux de parenthèses</translation>
    </message>
    <message>
        <source>condition nested too deeply: more than %1 levels of unary operators</source>
        <translation>réceptivité trop imbriquée&#xa0;: plus de %1 niveaux d&apos;opérateurs unaires</translation>
    </message>
    <message>
        <source>unmatched &apos;)&apos;: no &apos;(&apos; opens it</source>
        <translation>&apos;)&apos; sans correspondance&#xa0;: aucune &apos;(&apos; ne l&apos;ouvre</translation>
    </message>
    <message>
        <source>expected an operand before &apos;%1&apos;</source>
        <extracomment>%1: an operator the condition starts with</extracomment>
        <translation>opérande attendu avant &apos;%1&apos;</translation>
    </message>
    <message>
        <source>empty parentheses: expected an expression inside &apos;( )&apos;</source>
        <translation>parenthèses vides&#xa0;: une expression est attendue dans &apos;( )&apos;</translation>
    </message>
    <message>
        <source>expected an operand after &apos;%1&apos;</source>
        <extracomment>%1: the operator or &apos;(&apos; the condition ends with</extracomment>
        <translation>opérande attendu après &apos;%1&apos;</translation>
    </message>
    <message>
        <source>expected an operand after &apos;%1&apos;, found &apos;%2&apos;</source>
        <extracomment>%1: an operator or &apos;(&apos;; %2: what follows it instead of an operand</extracomment>
        <translation>opérande attendu après &apos;%1&apos;, trouvé &apos;%2&apos;</translation>
    </message>
    <message>
        <source>unmatched &apos;(&apos; at column %1: missing &apos;)&apos;</source>
        <extracomment>%1: a column number</extracomment>
        <translation>&apos;(&apos; sans correspondance à la colonne %1&#xa0;: &apos;)&apos; manquante</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos;: expected an operator or &apos;)&apos; to close the &apos;(&apos; at column %2</source>
        <extracomment>%1: what was found; %2: the column of the &apos;(&apos;</extracomment>
        <translation>&apos;%1&apos; inattendu&#xa0;: un opérateur ou &apos;)&apos; est attendu pour fermer la &apos;(&apos; de la colonne %2</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete condition</source>
        <translation>&apos;%1&apos; inattendu après une réceptivité complète</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete condition (missing operator?)</source>
        <translation>&apos;%1&apos; inattendu après une réceptivité complète (opérateur manquant&#xa0;?)</translation>
    </message>
    <message>
        <source>an edge (RE, FE, ↑, ↓) applies to a variable name</source>
        <translation>un front (RE, FE, ↑, ↓) s&apos;applique à un nom de variable</translation>
    </message>
    <message>
        <source>an edge (RE, FE, ↑, ↓) applies to a variable name, not to &apos;%1&apos;</source>
        <extracomment>%1: what follows RE, FE, ↑ or ↓ instead of a variable name</extracomment>
        <translation>un front (RE, FE, ↑, ↓) s&apos;applique à un nom de variable, pas à « %1 »</translation>
    </message>
    <message>
        <source>the duration &apos;%1&apos; must be followed by /X&lt;step&gt;, as in %1/X3</source>
        <extracomment>%1: a duration such as 5s; X3 is step 3&apos;s activity, keep it as is</extracomment>
        <translation>la durée « %1 » doit être suivie de /X&lt;étape&gt;, comme dans %1/X3</translation>
    </message>
    <message>
        <source>expected a step activity X&lt;step&gt; after &apos;/&apos; of the duration</source>
        <translation>activité d&apos;étape X&lt;étape&gt; attendue après le « / » de la durée</translation>
    </message>
    <message>
        <source>expected a step activity X&lt;step&gt; after &apos;/&apos; of the duration, found &apos;%1&apos;</source>
        <translation>activité d&apos;étape X&lt;étape&gt; attendue après le « / » de la durée, trouvé « %1 »</translation>
    </message>
    <message>
        <source>the duration &apos;%1&apos; is zero: write a positive duration</source>
        <translation>la durée « %1 » est nulle : écrivez une durée positive</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid duration: write for example 200ms, 5s, 1m30s or T#5s (units d, h, m, s, ms, largest first)</source>
        <translation>« %1 » n&apos;est pas une durée valide : écrivez par exemple 200ms, 5s, 1m30s ou T#5s (unités d, h, m, s, ms, de la plus grande à la plus petite)</translation>
    </message>
    <message>
        <source>empty action: write for example Valve, S Valve, R Valve or Count := Count + 1</source>
        <translation>action vide : écrivez par exemple Valve, S Valve, R Valve ou Count := Count + 1</translation>
    </message>
    <message>
        <source>an action writes a variable: &apos;%1&apos; is not a variable name</source>
        <translation>une action écrit une variable : « %1 » n&apos;est pas un nom de variable</translation>
    </message>
    <message>
        <source>the qualifier &apos;%1&apos; is not supported: use N (or none), S, R or an assignment V := value</source>
        <translation>le qualificatif « %1 » n&apos;est pas pris en charge : utilisez N (ou rien), S, R ou une affectation V := valeur</translation>
    </message>
    <message>
        <source>an assignment takes no qualifier: write V := value, without &apos;%1&apos;</source>
        <translation>une affectation ne prend pas de qualificatif : écrivez V := valeur, sans « %1 »</translation>
    </message>
    <message>
        <source>a stored action (%1) takes no IF condition: only continuous actions are conditional</source>
        <extracomment>%1: the qualifier S or R</extracomment>
        <translation>une action mémorisée (%1) ne prend pas de condition IF : seules les actions continues sont conditionnelles</translation>
    </message>
    <message>
        <source>expected a value after &apos;:=&apos;</source>
        <translation>valeur attendue après « := »</translation>
    </message>
    <message>
        <source>expected a condition after IF</source>
        <translation>condition attendue après IF</translation>
    </message>
    <message>
        <source>use := to assign a value; = compares</source>
        <translation>utilisez := pour affecter une valeur ; = compare</translation>
    </message>
    <message>
        <source>unexpected &apos;%1&apos; after a complete action</source>
        <translation>« %1 » inattendu après une action complète</translation>
    </message>
    <message>
        <source>empty condition: write when the transition fires (TRUE if it is always ready), or hide the transition if the machine does not need it</source>
        <translation>réceptivité vide&#xa0;: écrivez quand la transition est franchie (TRUE si elle est toujours prête), ou masquez la transition si la machine n&apos;en a pas besoin</translation>
    </message>
    <message>
        <source>a property starts with never or always</source>
        <translation>une propriété commence par never ou always</translation>
    </message>
    <message>
        <source>a property starts with never or always, not &apos;%1&apos;</source>
        <translation>une propriété commence par never ou always, pas par «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>expected a GEMMA step after &apos;in&apos;</source>
        <translation>une étape GEMMA est attendue après «&#xa0;in&#xa0;»</translation>
    </message>
    <message>
        <source>expected a GEMMA step after &apos;in&apos;, found &apos;%1&apos;</source>
        <translation>une étape GEMMA est attendue après «&#xa0;in&#xa0;», trouvé «&#xa0;%1&#xa0;»</translation>
    </message>
</context>
<context>
    <name>ConditionTypeErrorText</name>
    <message>
        <source>&apos;%1&apos; is an integer</source>
        <extracomment>%1: a subexpression of the condition</extracomment>
        <translation>&apos;%1&apos; est un entier</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a real number</source>
        <translation>&apos;%1&apos; est un nombre réel</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is of unknown type</source>
        <translation>&apos;%1&apos; est de type inconnu</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is %2</source>
        <extracomment>%1: a subexpression of the condition; %2: its IEC type (INT, BOOL)</extracomment>
        <translation>&apos;%1&apos; est de type %2</translation>
    </message>
    <message>
        <source>a condition must be BOOL, but %1</source>
        <extracomment>%1: the condition and what it is (&quot;&apos;Speed + 1&apos; is an integer&quot;)</extracomment>
        <translation>une réceptivité doit être BOOL, mais %1</translation>
    </message>
    <message>
        <source>%1 needs a BOOL operand, but %2</source>
        <extracomment>%1: NOT; %2: its operand and what it is (&quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 exige un opérande BOOL, mais %2</translation>
    </message>
    <message>
        <source>unary %1 needs a numeric operand, but %2</source>
        <extracomment>%1: &apos;-&apos; (negation); %2: its operand and what it is (&quot;&apos;Start&apos; is BOOL&quot;)</extracomment>
        <translation>le %1 unaire exige un opérande numérique, mais %2</translation>
    </message>
    <message>
        <source>%1 needs BOOL operands, but %2</source>
        <extracomment>%1: AND, OR or XOR; %2: the operand at fault and what it is (&quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 exige des opérandes BOOL, mais %2</translation>
    </message>
    <message>
        <source>%1 needs numeric operands, but %2</source>
        <extracomment>%1: a comparison or arithmetic operator (&apos;&lt;&apos;, &apos;+&apos;); %2: the operand at fault and what it is</extracomment>
        <translation>%1 exige des opérandes numériques, mais %2</translation>
    </message>
    <message>
        <source>%1 needs integer operands, but %2</source>
        <extracomment>%1: MOD; %2: the operand at fault and what it is (&quot;&apos;Temp&apos; is REAL&quot;)</extracomment>
        <translation>%1 exige des opérandes entiers, mais %2</translation>
    </message>
    <message>
        <source>%1 needs two operands of the same kind, but %2 and %3</source>
        <extracomment>%1: &apos;=&apos; or &apos;&lt;&gt;&apos;; %2, %3: each operand and what it is (&quot;&apos;Start&apos; is BOOL&quot;, &quot;&apos;Speed&apos; is INT&quot;)</extracomment>
        <translation>%1 exige deux opérandes de même nature, mais %2 et %3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range: integer literals go up to 9223372036854775807 (LINT)</source>
        <translation>&apos;%1&apos; est hors limites&#xa0;: les littéraux entiers vont jusqu&apos;à 9223372036854775807 (LINT)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range for LREAL (-1.8E308..1.8E308)</source>
        <translation>&apos;%1&apos; est hors limites pour LREAL (-1.8E308..1.8E308)</translation>
    </message>
</context>
<context>
    <name>ConveyorItem</name>
    <message>
        <source>Parts out: %1</source>
        <translation>Pièces sorties : %1</translation>
    </message>
</context>
<context>
    <name>DeclarationFixText</name>
    <message>
        <source>Declare &apos;%1&apos; as OUTPUT %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Déclarer « %1 » comme sortie %2</translation>
    </message>
    <message>
        <source>Declare &apos;%1&apos; as INTERNAL %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Déclarer « %1 » comme variable interne %2</translation>
    </message>
    <message>
        <source>Declare &apos;%1&apos; as INPUT %2</source>
        <extracomment>A quick fix; %2: an IEC type name (BOOL, INT)</extracomment>
        <translation>Déclarer « %1 » comme entrée %2</translation>
    </message>
</context>
<context>
    <name>DiagnosticText</name>
    <message>
        <source>the name is empty</source>
        <translation>le nom est vide</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a valid IEC 61131-3 identifier: use ASCII letters, digits and &apos;_&apos;, not starting with a digit</source>
        <translation>&apos;%1&apos; n&apos;est pas un identificateur IEC 61131-3 valide&#xa0;: utilisez des lettres ASCII, des chiffres et &apos;_&apos;, sans commencer par un chiffre</translation>
    </message>
    <message>
        <source>&apos;%1&apos; contains &apos;__&apos;, which IEC 61131-3 identifiers may not</source>
        <translation>&apos;%1&apos; contient &apos;__&apos;, ce que les identificateurs IEC 61131-3 n&apos;autorisent pas</translation>
    </message>
    <message>
        <source>&apos;%1&apos; ends with &apos;_&apos;, which IEC 61131-3 identifiers may not</source>
        <translation>&apos;%1&apos; se termine par &apos;_&apos;, ce que les identificateurs IEC 61131-3 n&apos;autorisent pas</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is an IEC 61131-3 keyword or type name</source>
        <translation>&apos;%1&apos; est un mot-clé ou un nom de type IEC 61131-3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is a name the generated code uses</source>
        <translation>&apos;%1&apos; est un nom utilisé par le code généré</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; does not occur in the condition.</source>
        <translation>La mémoire de &apos;%2&apos; dans %1 est invalide&#xa0;: &apos;%2&apos; n&apos;apparaît pas dans la réceptivité.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is ambiguous: the condition uses both %2 and NOT %2, so the token could be neither normally open nor normally closed.</source>
        <translation>La mémoire de &apos;%2&apos; dans %1 est ambiguë&#xa0;: la réceptivité utilise à la fois %2 et NOT %2, la mémoire ne peut donc être ni normalement ouverte ni normalement fermée.</translation>
    </message>
    <message>
        <source>The token in %1 names &apos;%2&apos;, which is not a declared variable.</source>
        <translation>Une mémoire de %1 porte sur &apos;%2&apos;, qui n&apos;est pas une variable déclarée.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; is compared with &apos;=&apos; or &apos;&lt;&gt;&apos; in the condition, where it has no polarity; a token can only replace a literal %2 or NOT %2.</source>
        <translation>La mémoire de &apos;%2&apos; dans %1 est invalide&#xa0;: &apos;%2&apos; est comparée avec &apos;=&apos; ou &apos;&lt;&gt;&apos; dans la réceptivité, où elle n&apos;a pas de polarité&#xa0;; une mémoire ne peut remplacer qu&apos;un littéral %2 ou NOT %2.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 has no effect and is not generated: family transitions never wait for Complete.</source>
        <translation>La mémoire de &apos;%2&apos; dans %1 n&apos;a aucun effet et n&apos;est pas générée&#xa0;: les transitions de famille n&apos;attendent jamais Complete.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 has no effect and is not generated: its source %3 is a simple step.</source>
        <translation>La mémoire de &apos;%2&apos; dans %1 n&apos;a aucun effet et n&apos;est pas générée&#xa0;: son étape source %3 est une étape simple.</translation>
    </message>
    <message>
        <source>The initial step %1 is hidden: the PLC would start in a state that has no code.</source>
        <translation>L&apos;étape initiale %1 est masquée&#xa0;: l&apos;automate démarrerait dans un état sans code.</translation>
    </message>
    <message>
        <source>Step %1 has no visible outgoing transition: the machine would stay in it forever.</source>
        <translation>L&apos;étape %1 n&apos;a aucune transition de sortie visible&#xa0;: la machine y resterait indéfiniment.</translation>
    </message>
    <message>
        <source>Step %1 has no visible incoming transition: it can never become active.</source>
        <translation>L&apos;étape %1 n&apos;a aucune transition d&apos;entrée visible&#xa0;: elle ne peut jamais devenir active.</translation>
    </message>
    <message>
        <source>The family transition %1 is negated, which has no effect: family transitions never wait for Complete.</source>
        <translation>La transition de famille %1 est niée, ce qui n&apos;a aucun effet&#xa0;: les transitions de famille n&apos;attendent jamais Complete.</translation>
    </message>
    <message>
        <source>The condition of %1 is FALSE: the transition can never fire (hide it instead).</source>
        <translation>La réceptivité de %1 est FALSE&#xa0;: la transition ne peut jamais être franchie (masquez-la plutôt).</translation>
    </message>
    <message>
        <source>Step %1 cannot be reached from the initial step %2 through visible transitions: it can never become active.</source>
        <translation>L&apos;étape %1 n&apos;est pas accessible depuis l&apos;étape initiale %2 par des transitions visibles&#xa0;: elle ne peut jamais devenir active.</translation>
    </message>
    <message>
        <source>Transition %1 is negated, which has no effect: its source %2 is a simple step, and negation only changes transitions out of macro and enclosing steps.</source>
        <translation>La transition %1 est niée, ce qui n&apos;a aucun effet&#xa0;: son étape source %2 est une étape simple, et la négation ne change que les transitions issues de macro-étapes et d&apos;étapes encapsulantes.</translation>
    </message>
    <message>
        <source>The condition of %1 is TRUE and does not wait for Complete: the lower-priority transitions %2 can never fire.</source>
        <translation>La réceptivité de %1 est TRUE et n&apos;attend pas Complete&#xa0;: les transitions moins prioritaires %2 ne peuvent jamais être franchies.</translation>
    </message>
    <message>
        <source>Invalid variable name: %1.</source>
        <translation>Nom de variable invalide&#xa0;: %1.</translation>
    </message>
    <message>
        <source>Syntax error in the condition of %1: %2.</source>
        <translation>Erreur de syntaxe dans la réceptivité de %1&#xa0;: %2.</translation>
    </message>
    <message>
        <source>In the condition of %1: &apos;%2&apos; is not a declared variable.</source>
        <translation>Dans la réceptivité de %1&#xa0;: &apos;%2&apos; n&apos;est pas une variable déclarée.</translation>
    </message>
    <message>
        <source>Type error in the condition of %1: %2.</source>
        <translation>Erreur de type dans la réceptivité de %1&#xa0;: %2.</translation>
    </message>
    <message>
        <source>The token on &apos;%2&apos; in %1 is invalid: &apos;%2&apos; is %3, and only BOOL variables can have a token.</source>
        <translation>La mémoire de &apos;%2&apos; dans %1 est invalide&#xa0;: &apos;%2&apos; est de type %3, et seules les variables BOOL peuvent avoir une mémoire.</translation>
    </message>
    <message>
        <source>The default value of variable &apos;%1&apos; is invalid: %2.</source>
        <translation>La valeur initiale de la variable &apos;%1&apos; est invalide&#xa0;: %2.</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Erreur</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Avertissement</translation>
    </message>
    <message>
        <source>Information</source>
        <translation>Information</translation>
    </message>
    <message>
        <source>The verification reached its time or size limit before every property was decided: the properties not reported were not decided.</source>
        <translation>La vérification a atteint sa limite de temps ou de taille avant que toutes les propriétés soient décidées&#xa0;: les propriétés non signalées n&apos;ont pas été décidées.</translation>
    </message>
    <message>
        <source>The verification reached its time or size limit before deciding everything about %1: what is not reported about it was not decided. Every other finding holds.</source>
        <translation>La vérification a atteint sa limite de temps ou de taille avant de tout décider sur %1&#xa0;: ce qui n&apos;est pas signalé à son sujet n&apos;a pas été décidé. Tous les autres résultats sont valables.</translation>
    </message>
    <message>
        <source>Step %1 can never become active: no effective transition leads to it.</source>
        <translation>L&apos;étape %1 ne peut jamais devenir active&#xa0;: aucune transition effective n&apos;y mène.</translation>
    </message>
    <message>
        <source>Step %1 can never become active: no situation reachable from the initial step lets %2 fire.</source>
        <translation>L&apos;étape %1 ne peut jamais devenir active&#xa0;: aucune situation accessible depuis l&apos;étape initiale ne permet de franchir %2.</translation>
    </message>
    <message>
        <source>Transition %1 can never fire: its condition is never TRUE in a situation reachable from the initial step.</source>
        <translation>La transition %1 ne peut jamais être franchie&#xa0;: sa réceptivité n&apos;est TRUE dans aucune situation accessible depuis l&apos;étape initiale.</translation>
    </message>
    <message>
        <source>Transition %1 can never fire: whenever its condition holds, a transition of higher priority fires first (%2).</source>
        <translation>La transition %1 ne peut jamais être franchie&#xa0;: chaque fois que sa réceptivité est vraie, une transition plus prioritaire est franchie avant elle (%2).</translation>
    </message>
    <message>
        <source>The condition of %1 is always TRUE: no own transition of an F step can ever fire.</source>
        <translation>La réceptivité de %1 est toujours TRUE&#xa0;: aucune transition propre d&apos;une étape F ne peut jamais être franchie.</translation>
    </message>
    <message>
        <source>The condition of %1 is always TRUE when %3 is active: %2 can never fire.</source>
        <translation>La réceptivité de %1 est toujours TRUE quand %3 est active&#xa0;: %2 ne peut jamais être franchie.</translation>
    </message>
    <message>
        <source>%1 and %2 can both be TRUE in the same scan: the priority decides, %1 fires.</source>
        <translation>%1 et %2 peuvent être TRUE dans le même cycle&#xa0;: la priorité décide, %1 est franchie.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead to a situation from which the initial step can never become active again.</source>
        <translation>Une fois %1 active, les entrées peuvent mener à une situation d&apos;où l&apos;étape initiale ne peut plus jamais redevenir active.</translation>
    </message>
    <message>
        <source>Step %1 can get stuck: the inputs can lead to a situation in it from which no transition out of it can ever fire.</source>
        <translation>L&apos;étape %1 peut se bloquer&#xa0;: les entrées peuvent mener à une situation où aucune de ses transitions de sortie ne peut plus jamais être franchie.</translation>
    </message>
    <message>
        <source>The emergency stop D1 can never be entered from %1: the family transition F-&gt;D1 is not effective and %1 has no transition to D1.</source>
        <translation>L&apos;arrêt d&apos;urgence D1 ne peut jamais être atteint depuis %1&#xa0;: la transition de famille F-&gt;D1 n&apos;est pas effective et %1 n&apos;a aucune transition vers D1.</translation>
    </message>
    <message>
        <source>In some situations of %1 the emergency stop D1 cannot be entered in one scan, whatever the inputs: %2 cannot fire there.</source>
        <translation>Dans certaines situations de %1, l&apos;arrêt d&apos;urgence D1 ne peut pas être atteint en un cycle, quelles que soient les entrées&#xa0;: %2 ne peut pas y être franchie.</translation>
    </message>
    <message>
        <source>Not confirmed: a condition uses a comparison the verifier cannot decide, and the counterexample does not replay.</source>
        <translation>Non confirmé&#xa0;: une réceptivité utilise une comparaison que le vérificateur ne sait pas trancher, et le contre-exemple ne se rejoue pas.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 has no initial step: it would never do anything.</source>
        <translation>Le GRAFCET de %1 n&apos;a pas d&apos;étape initiale : il ne ferait jamais rien.</translation>
    </message>
    <message>
        <source>Step %2 of %1 cannot be reached from the initial steps through transitions: it can never become active.</source>
        <translation>L&apos;étape %2 de %1 ne peut pas être atteinte depuis les étapes initiales par des transitions : elle ne peut jamais devenir active.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 never sets Complete, so %2, which wait for it, can never fire.</source>
        <extracomment>%2: the GEMMA transitions that wait for Complete</extracomment>
        <translation>Le GRAFCET de %1 ne met jamais Complete à vrai : %2, qui l&apos;attendent, ne peuvent jamais être franchies.</translation>
    </message>
    <message>
        <source>The selection after step %2 of %1 is not exclusive: %3 and %4 can both fire (with %5), and both branches then start.</source>
        <extracomment>%3, %4: two nested transitions; %5: the values that make both receptivities TRUE</extracomment>
        <translation>La sélection après l&apos;étape %2 de %1 n&apos;est pas exclusive : %3 et %4 peuvent être franchies ensemble (avec %5), et les deux branches démarrent alors.</translation>
    </message>
    <message>
        <source>Step %2 of %1 has no outgoing transition and does not set Complete: the GRAFCET stops there for good.</source>
        <translation>L&apos;étape %2 de %1 n&apos;a pas de transition aval et ne met pas Complete à vrai : le GRAFCET s&apos;y arrête définitivement.</translation>
    </message>
    <message>
        <source>Under the until-stable rule, step %2 of %1 is left in the call that enters it (%3 is always TRUE): the GEMMA layer never sees what it does to Complete.</source>
        <translation>Avec la règle « jusqu&apos;à stabilité », l&apos;étape %2 de %1 est quittée dans l&apos;appel qui l&apos;active (%3 est toujours vraie) : la couche GEMMA ne voit jamais ce qu&apos;elle fait de Complete.</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has a name the code of the nested GRAFCETs uses: %2.</source>
        <extracomment>%2: why, in English (a technical reason)</extracomment>
        <translation>La variable « %1 » porte un nom qu&apos;utilise le code des GRAFCET imbriqués : %2.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 is kept but not used: %1 is hidden.</source>
        <translation>Le GRAFCET de %1 est conservé mais inutilisé : %1 est masquée.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 is kept but not used: %1 is a simple step.</source>
        <translation>Le GRAFCET de %1 est conservé mais inutilisé : %1 est une étape simple.</translation>
    </message>
    <message>
        <source>The condition of %1 is empty: write when it fires (TRUE if it is always ready), or hide the transition if your machine does not need it.</source>
        <translation>La réceptivité de %1 est vide&#xa0;: écrivez quand elle est franchie (TRUE si elle est toujours prête), ou masquez la transition si votre machine n&apos;en a pas besoin.</translation>
    </message>
    <message>
        <source>Step %2 of the nested GRAFCET of %1 can never become active.</source>
        <extracomment>%1: a GEMMA step; %2: the number of a step of its nested GRAFCET</extracomment>
        <translation>L&apos;étape %2 du GRAFCET imbriqué de %1 ne peut jamais devenir active.</translation>
    </message>
    <message>
        <source>Transition T%2 of the nested GRAFCET of %1 can never fire.</source>
        <extracomment>%1: a GEMMA step; %2: the number of a transition of its nested GRAFCET</extracomment>
        <translation>La transition T%2 du GRAFCET imbriqué de %1 ne peut jamais être franchie.</translation>
    </message>
    <message>
        <source>Step %2 of the nested GRAFCET of %1 can be activated while it is already active: the GRAFCET is not safe.</source>
        <translation>L&apos;étape %2 du GRAFCET imbriqué de %1 peut être activée alors qu&apos;elle est déjà active&#xa0;: le GRAFCET n&apos;est pas sauf.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 can be Unstable: its evolutions do not settle within one scan.</source>
        <translation>Le GRAFCET imbriqué de %1 peut être instable (Unstable)&#xa0;: ses évolutions ne se stabilisent pas en un cycle.</translation>
    </message>
    <message>
        <source>Transitions T%3 and T%4 of the nested GRAFCET of %1 can fire together from step %2: both branches of the selection start.</source>
        <extracomment>%2: a nested step; %3, %4: the numbers of two nested transitions</extracomment>
        <translation>Les transitions T%3 et T%4 du GRAFCET imbriqué de %1 peuvent être franchies ensemble depuis l&apos;étape %2&#xa0;: les deux branches de la sélection démarrent.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead its nested GRAFCET to a situation from which Complete never becomes TRUE.</source>
        <translation>Une fois %1 active, les entrées peuvent mener son GRAFCET imbriqué à une situation d&apos;où Complete ne devient jamais TRUE.</translation>
    </message>
    <message>
        <source>Once %1 is active, the inputs can lead its nested GRAFCET to a situation from which Complete never becomes TRUE: %2 can no longer fire.</source>
        <extracomment>%2: the GEMMA transitions that wait for Complete</extracomment>
        <translation>Une fois %1 active, les entrées peuvent mener son GRAFCET imbriqué à une situation d&apos;où Complete ne devient jamais TRUE&#xa0;: %2 ne peut plus être franchie.</translation>
    </message>
    <message>
        <source>%1 waits for the Complete of %2, which never becomes TRUE: it can never fire.</source>
        <translation>%1 attend le Complete de %2, qui ne devient jamais TRUE&#xa0;: elle ne peut jamais être franchie.</translation>
    </message>
    <message>
        <source>Steps %2 and %3 of the nested GRAFCET of %1 can write different values to &apos;%4&apos; in the same scan: the result depends on the order of the actions.</source>
        <translation>Les étapes %2 et %3 du GRAFCET imbriqué de %1 peuvent écrire des valeurs différentes dans «&#xa0;%4&#xa0;» au même cycle&#xa0;: le résultat dépend de l&apos;ordre des actions.</translation>
    </message>
    <message>
        <source>The continuous output &apos;%2&apos; can still be TRUE in the scan in which the emergency stop %1 is entered.</source>
        <translation>La sortie continue «&#xa0;%2&#xa0;» peut encore être TRUE au cycle où l&apos;on entre dans l&apos;arrêt d&apos;urgence %1.</translation>
    </message>
    <message>
        <source>The stored output &apos;%2&apos; can still be TRUE in the scan in which the emergency stop %1 is entered: stored actions are memories, only continuous outputs drop with the state.</source>
        <translation>La sortie mémorisée «&#xa0;%2&#xa0;» peut encore être TRUE au cycle où l&apos;on entre dans l&apos;arrêt d&apos;urgence %1&#xa0;: les actions mémorisées sont des mémoires, seules les sorties continues tombent avec l&apos;état.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; does not hold.</source>
        <translation>La propriété «&#xa0;%1&#xa0;» n&apos;est pas vérifiée.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; holds in every reachable scan, with the abstractions the verification lists.</source>
        <translation>La propriété «&#xa0;%1&#xa0;» est vraie à chaque cycle atteignable, avec les abstractions que la vérification indique.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; holds in every reachable scan.</source>
        <translation>La propriété «&#xa0;%1&#xa0;» est vraie à chaque cycle atteignable.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; cannot be checked: it is empty.</source>
        <translation>La propriété «&#xa0;%1&#xa0;» ne peut pas être vérifiée&#xa0;: elle est vide.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; cannot be checked: %2.</source>
        <extracomment>%2: why, in English (the property checker&apos;s message)</extracomment>
        <translation>La propriété «&#xa0;%1&#xa0;» ne peut pas être vérifiée&#xa0;: %2.</translation>
    </message>
    <message>
        <source>The exploration of both layers reached its time or size limit: what it found is reported, but nothing about the nested GRAFCETs or the properties is proved.</source>
        <translation>L&apos;exploration des deux niveaux a atteint sa limite de temps ou de taille&#xa0;: ce qu&apos;elle a trouvé est signalé, mais rien n&apos;est prouvé sur les GRAFCET imbriqués ni sur les propriétés.</translation>
    </message>
    <message>
        <source>Not confirmed: the run found under the abstractions of the verification does not replay in the simulator.</source>
        <translation>Non confirmé&#xa0;: l&apos;exécution trouvée sous les abstractions de la vérification ne se rejoue pas dans le simulateur.</translation>
    </message>
    <message>
        <source>Not confirmed: decided on the GEMMA layer with every Complete free, and the run does not replay with the nested GRAFCETs.</source>
        <translation>Non confirmé&#xa0;: décidé sur la couche GEMMA avec chaque Complete libre, et l&apos;exécution ne se rejoue pas avec les GRAFCET imbriqués.</translation>
    </message>
    <message>
        <source>In the condition of %1: &apos;%2&apos; divides by zero: on the PLC an integer division or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / 0)</extracomment>
        <translation>Dans la réceptivité de %1 : &apos;%2&apos; divise par zéro : sur l&apos;automate, une division entière ou un MOD par zéro arrête la tâche sur un défaut, et une division REAL donne INF ou NaN.</translation>
    </message>
    <message>
        <source>In the condition of %1: the divisor of &apos;%2&apos; can be zero: an integer division or MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / Batch)</extracomment>
        <translation>Dans la réceptivité de %1 : le diviseur de &apos;%2&apos; peut être nul : une division entière ou un MOD par zéro arrête l&apos;automate sur un défaut (et la simulation), une division REAL donne INF ou NaN.</translation>
    </message>
    <message>
        <source>The property &apos;%1&apos; is undecided: neither proved nor shown violated (%2).</source>
        <extracomment>%2: why, in English (the verifier&apos;s reason)</extracomment>
        <translation>La propriété « %1 » est indécise : ni prouvée ni montrée violée (%2).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the function block of enclosing step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variable « %1 » porte le nom du bloc fonctionnel de l&apos;étape encapsulante %2 dans le code généré : renommez la variable (par exemple en « %3 »).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the function block of macro-step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variable « %1 » porte le nom du bloc fonctionnel de la macro-étape %2 dans le code généré : renommez la variable (par exemple en « %3 »).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the instance of enclosing step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variable « %1 » porte le nom de l&apos;instance de l&apos;étape encapsulante %2 dans le code généré : renommez la variable (par exemple en « %3 »).</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; has the name of the instance of macro-step %2 in the generated code: rename the variable (for example to &apos;%3&apos;).</source>
        <translation>La variable « %1 » porte le nom de l&apos;instance de la macro-étape %2 dans le code généré : renommez la variable (par exemple en « %3 »).</translation>
    </message>
    <message>
        <source>Enclosing step %1 declares its function block %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>L&apos;étape encapsulante %1 déclare son bloc fonctionnel %2 dans le code généré, et la variable « %3 » porte ce nom : renommez la variable (par exemple en « %4 »), ou faites de %1 une étape simple.</translation>
    </message>
    <message>
        <source>Macro-step %1 declares its function block %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La macro-étape %1 déclare son bloc fonctionnel %2 dans le code généré, et la variable « %3 » porte ce nom : renommez la variable (par exemple en « %4 »), ou faites de %1 une étape simple.</translation>
    </message>
    <message>
        <source>Enclosing step %1 declares its instance %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>L&apos;étape encapsulante %1 déclare son instance %2 dans le code généré, et la variable « %3 » porte ce nom : renommez la variable (par exemple en « %4 »), ou faites de %1 une étape simple.</translation>
    </message>
    <message>
        <source>Macro-step %1 declares its instance %2 in the generated code, and variable &apos;%3&apos; has that name: rename the variable (for example to &apos;%4&apos;), or make %1 a simple step.</source>
        <translation>La macro-étape %1 déclare son instance %2 dans le code généré, et la variable « %3 » porte ce nom : renommez la variable (par exemple en « %4 »), ou faites de %1 une étape simple.</translation>
    </message>
    <message>
        <source>%2 is read in %3 and by its level in %4, which can fire right after it: while %2 stays TRUE, both fire in the same scan and step %5 of %1 is passed through; read its rising edge in %4 (↑%2) so that each press fires one transition.</source>
        <extracomment>%2: a BOOL input; %3, %4: two nested transitions; %5: the steps between them</extracomment>
        <translation>%2 est lue dans %3 et sur son niveau dans %4, qui peut être franchie juste après : tant que %2 reste à TRUE, les deux sont franchies dans le même cycle et l&apos;étape %5 de %1 est traversée ; lisez son front montant dans la réceptivité de %4 (↑%2) pour que chaque appui franchisse une seule transition.</translation>
    </message>
    <message>
        <source>%2 is read in %3 and by its level in %4, which can fire right after it: while %2 stays TRUE, both fire in consecutive scans and step %5 of %1 is passed through; read its rising edge in %4 (↑%2) so that each press fires one transition.</source>
        <translation>%2 est lue dans %3 et sur son niveau dans %4, qui peut être franchie juste après : tant que %2 reste à TRUE, les deux sont franchies dans des cycles consécutifs et l&apos;étape %5 de %1 est traversée ; lisez son front montant dans la réceptivité de %4 (↑%2) pour que chaque appui franchisse une seule transition.</translation>
    </message>
    <message>
        <source>The selection after step %2 of %1 is not complete: with %4 none of %3 fires and the GRAFCET waits in step %2; add a branch for these values unless waiting is intended.</source>
        <extracomment>%3: the branches (T1, T2); %4: values of the variables (CP1 = TRUE, CP2 = FALSE)</extracomment>
        <translation>La sélection après l&apos;étape %2 de %1 n&apos;est pas complète : avec %4, aucune de %3 n&apos;est franchie et le GRAFCET attend à l&apos;étape %2 ; ajoutez une branche pour ces valeurs, sauf si l&apos;attente est voulue.</translation>
    </message>
    <message>
        <source>Not confirmed: its counterexample does not replay to it in the simulator.</source>
        <translation>Non confirmé : son contre-exemple ne le reproduit pas dans le simulateur.</translation>
    </message>
    <message>
        <source>Variable &apos;%1&apos; is used by no condition, receptivity or action that generates code.</source>
        <translation>La variable &apos;%1&apos; n&apos;est utilisée par aucune condition, réceptivité ou action qui génère du code.</translation>
    </message>
    <message>
        <source>Not confirmed: the run found under the abstractions of the verification does not replay in the simulator, and the search for one with time counted in scans stopped at the time or size limit (a longer time limit may find it).</source>
        <translation>Non confirmé&#xa0;: l&apos;exécution trouvée sous les abstractions de la vérification ne se rejoue pas dans le simulateur, et la recherche d&apos;une exécution avec le temps compté en cycles s&apos;est arrêtée à la limite de temps ou de taille (une limite de temps plus longue peut la trouver).</translation>
    </message>
</context>
<context>
    <name>EditMachineComponentCommand</name>
    <message>
        <source>Edit %1</source>
        <translation>Modifier %1</translation>
    </message>
</context>
<context>
    <name>ElementLabels</name>
    <message>
        <source>F (family)</source>
        <translation>F (famille)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <extracomment>a transition: source step, arrow, target step</extracomment>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Simple step</source>
        <translation>Étape simple</translation>
    </message>
    <message>
        <source>Macro-step</source>
        <translation>Macro-étape</translation>
    </message>
    <message>
        <source>Enclosing step</source>
        <translation>Étape encapsulante</translation>
    </message>
    <message>
        <source>hidden</source>
        <translation>masquée</translation>
    </message>
    <message>
        <source>source %1 hidden</source>
        <translation>étape source %1 masquée</translation>
    </message>
    <message>
        <source>target %1 hidden</source>
        <translation>étape cible %1 masquée</translation>
    </message>
</context>
<context>
    <name>ExampleModels</name>
    <message>
        <source>Drilling Cell</source>
        <translation>Cellule de perçage</translation>
    </message>
    <message>
        <source>A machine that clamps, drills and marks parts: GEMMA states with four nested GRAFCETs, ready to simulate</source>
        <translation>Une machine qui bride, perce et marque des pièces&#xa0;: des états GEMMA avec quatre GRAFCET imbriqués, prête à simuler</translation>
    </message>
    <message>
        <source>Drilling Cell with Mistakes</source>
        <translation>Cellule de perçage avec erreurs</translation>
    </message>
    <message>
        <source>The same machine with one mistake for each check of the nested GRAFCETs, to see what the Problems panel reports</source>
        <translation>La même machine avec une erreur pour chaque vérification des GRAFCET imbriqués, pour voir ce que signale le panneau Problèmes</translation>
    </message>
    <message>
        <source>The example %1 is missing from this build.</source>
        <translation>L&apos;exemple %1 est absent de cette version.</translation>
    </message>
    <message>
        <source>Bottle Filler (PackML)</source>
        <translation>Remplisseuse de bouteilles (PackML)</translation>
    </message>
    <message>
        <source>A PackML unit with Production and Manual modes and a GRAFCET in Resetting, Starting, Execute, Stopping and Aborting</source>
        <translation>Une unité PackML avec les modes Production et Manual et un GRAFCET dans Resetting, Starting, Execute, Stopping et Aborting</translation>
    </message>
</context>
<context>
    <name>FaultMenu</name>
    <message>
        <source>Fault not injected</source>
        <translation>Défaillance non injectée</translation>
    </message>
    <message>
        <source>stuck at TRUE</source>
        <extracomment>a fault of a sensor of the virtual machine, shown beside its value</extracomment>
        <translation>bloqué à TRUE</translation>
    </message>
    <message>
        <source>stuck at FALSE</source>
        <translation>bloqué à FALSE</translation>
    </message>
    <message>
        <source>flickering</source>
        <translation>instable</translation>
    </message>
    <message>
        <source>stuck TRUE</source>
        <extracomment>a sensor&apos;s fault where space is short (the Machine tab); TRUE and FALSE stay as they are</extracomment>
        <translation>bloqué TRUE</translation>
    </message>
    <message>
        <source>stuck FALSE</source>
        <translation>bloqué FALSE</translation>
    </message>
    <message>
        <source>flicker</source>
        <translation>instable</translation>
    </message>
    <message>
        <source>Fault of %1</source>
        <extracomment>%1: a sensor variable of the virtual machine
----------
%1: a cylinder or conveyor of the virtual machine</extracomment>
        <translation>Défaillance de %1</translation>
    </message>
    <message>
        <source>Stuck at &amp;TRUE</source>
        <translation>Bloqué à &amp;TRUE</translation>
    </message>
    <message>
        <source>Stuck at &amp;FALSE</source>
        <translation>Bloqué à &amp;FALSE</translation>
    </message>
    <message>
        <source>F&amp;licker</source>
        <translation>&amp;Instable</translation>
    </message>
    <message>
        <source>&amp;Clear Fault</source>
        <translation>&amp;Effacer la défaillance</translation>
    </message>
    <message>
        <source>Clear &amp;Jam</source>
        <translation>&amp;Débloquer</translation>
    </message>
    <message>
        <source>&amp;Jam</source>
        <translation>&amp;Bloquer</translation>
    </message>
</context>
<context>
    <name>GrafcetClipboard</name>
    <message>
        <source>The clipboard holds no GRAFCET steps</source>
        <translation>Le presse-papiers ne contient aucune étape de GRAFCET</translation>
    </message>
    <message>
        <source>Nothing pasted: the GRAFCET steps on the clipboard are damaged (%1)</source>
        <extracomment>%1 what is wrong in the clipboard&apos;s data (in English), with where when known</extracomment>
        <translation>Rien n’a été collé : les étapes de GRAFCET du presse-papiers sont endommagées (%1)</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Étape %1</translation>
    </message>
    <message>
        <source>T%1 (%2 → %3): %4</source>
        <extracomment>a transition copied as text: %1 its number, %2 and %3 the steps it links, %4 its receptivity</extracomment>
        <translation>T%1 (%2 → %3) : %4</translation>
    </message>
</context>
<context>
    <name>GrafcetExport</name>
    <message>
        <source>Nested GRAFCET drawn by GG Studio</source>
        <translation>GRAFCET imbriqué dessiné avec GG Studio</translation>
    </message>
</context>
<context>
    <name>InitialStepRule</name>
    <message>
        <source>%1 is the initial step, which cannot be hidden; make another step initial first</source>
        <extracomment>%1 is a GEMMA step, e.g. A1</extracomment>
        <translation>%1 est l&apos;étape initiale, qui ne peut pas être masquée ; rendez d&apos;abord une autre étape initiale</translation>
    </message>
    <message>
        <source>%1 is hidden and cannot be the initial step; show it first</source>
        <extracomment>%1 is a GEMMA step, e.g. A3</extracomment>
        <translation>%1 est masquée et ne peut pas être l&apos;étape initiale ; affichez-la d&apos;abord</translation>
    </message>
</context>
<context>
    <name>MachineComponentItem</name>
    <message>
        <source>%1: %2</source>
        <extracomment>%1: a role of a machine component (&quot;extended&quot;); %2: the variable wired to it
----------
%1: a sensor variable (&quot;Clamped&quot;); %2: its fault (&quot;stuck FALSE&quot;)</extracomment>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>(not wired)</source>
        <translation>(non câblé)</translation>
    </message>
    <message>
        <source>%1, jammed</source>
        <extracomment>%1: the kind of a machine component (&quot;Double-acting cylinder&quot;), which a fault has stopped</extracomment>
        <translation>%1, bloqué</translation>
    </message>
</context>
<context>
    <name>MachineDiagnosticText</name>
    <message>
        <source>an input</source>
        <translation>une entrée</translation>
    </message>
    <message>
        <source>an output</source>
        <translation>une sortie</translation>
    </message>
    <message>
        <source>an internal variable</source>
        <translation>une variable interne</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal names &apos;%3&apos;, which is no variable of the model.</source>
        <extracomment>%1: a machine component; %2: its role (extend, retracted...); %3: a name</extracomment>
        <translation>Le signal %2 de %1 désigne « %3 », qui n&apos;est pas une variable du modèle.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal is %3, %4; it needs %5.</source>
        <extracomment>%1: a machine component; %2: its role; %3: a variable; %4, %5: &quot;an input&quot;, &quot;an output&quot;...</extracomment>
        <translation>Le signal %2 de %1 est %3, %4 ; il lui faut %5.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal is %3, of type %4; a machine signal is BOOL.</source>
        <extracomment>%4: an IEC type (INT)</extracomment>
        <translation>Le signal %2 de %1 est %3, de type %4 ; un signal de la machine est BOOL.</translation>
    </message>
    <message>
        <source>%3 is wired to %1&apos;s %2 signal and to %4&apos;s %5 signal: an input has one source.</source>
        <extracomment>%1, %4: machine components; %2, %5: their roles; %3: the input both are wired to</extracomment>
        <translation>%3 est câblée au signal %2 de %1 et au signal %5 de %4 : une entrée a une seule source.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 signal %3 is driven by no action of the program: the component never moves.</source>
        <translation>Le signal %2 (%3) de %1 n&apos;est piloté par aucune action du programme : le composant ne bouge jamais.</translation>
    </message>
    <message>
        <source>%1&apos;s %2 is %3: out of range (travel times 1 to 3600000 ms, delays 0 to 3600000 ms, parts 0 to 1000000000).</source>
        <extracomment>%2: a parameter (extendMs, onDelayMs, parts); %3: its value</extracomment>
        <translation>%2 de %1 vaut %3 : hors limites (temps de course 1 à 3600000 ms, retards 0 à 3600000 ms, pièces 0 à 1000000000).</translation>
    </message>
    <message>
        <source>%1 has no variable for its %2 signal.</source>
        <translation>%1 n&apos;a pas de variable pour son signal %2.</translation>
    </message>
    <message>
        <source>%1 feeds &apos;%2&apos;, which is no conveyor of the machine.</source>
        <translation>%1 alimente « %2 », qui n&apos;est pas un convoyeur de la machine.</translation>
    </message>
</context>
<context>
    <name>MachineText</name>
    <message>
        <source>Double-acting cylinder</source>
        <translation>Vérin double effet</translation>
    </message>
    <message>
        <source>Single-acting cylinder</source>
        <translation>Vérin simple effet</translation>
    </message>
    <message>
        <source>Conveyor</source>
        <translation>Convoyeur</translation>
    </message>
    <message>
        <source>Lamp</source>
        <translation>Voyant</translation>
    </message>
    <message>
        <source>Push button</source>
        <translation>Bouton-poussoir</translation>
    </message>
    <message>
        <source>Selector</source>
        <translation>Sélecteur</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Arrêt d&apos;urgence</translation>
    </message>
    <message>
        <source>Delayed sensor</source>
        <translation>Capteur temporisé</translation>
    </message>
    <message>
        <source>Part source</source>
        <translation>Source de pièces</translation>
    </message>
    <message>
        <source>extend</source>
        <translation>sortir</translation>
    </message>
    <message>
        <source>retract</source>
        <translation>rentrer</translation>
    </message>
    <message>
        <source>retracted</source>
        <translation>rentré</translation>
    </message>
    <message>
        <source>extended</source>
        <translation>sorti</translation>
    </message>
    <message>
        <source>run</source>
        <translation>marche</translation>
    </message>
    <message>
        <source>part present</source>
        <translation>pièce présente</translation>
    </message>
    <message>
        <source>lamp</source>
        <translation>voyant</translation>
    </message>
    <message>
        <source>input</source>
        <translation>entrée</translation>
    </message>
    <message>
        <source>output</source>
        <translation>sortie</translation>
    </message>
    <message>
        <source>sensor</source>
        <translation>capteur</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>vide</translation>
    </message>
    <message>
        <source>Extend time (ms)</source>
        <translation>Temps de sortie (ms)</translation>
    </message>
    <message>
        <source>Retract time (ms)</source>
        <translation>Temps de rentrée (ms)</translation>
    </message>
    <message>
        <source>Travel time (ms)</source>
        <translation>Temps de trajet (ms)</translation>
    </message>
    <message>
        <source>On delay (ms)</source>
        <translation>Retard à l&apos;enclenchement (ms)</translation>
    </message>
    <message>
        <source>Off delay (ms)</source>
        <translation>Retard au déclenchement (ms)</translation>
    </message>
    <message>
        <source>Parts</source>
        <translation>Pièces</translation>
    </message>
    <message>
        <source>Normally closed</source>
        <translation>Normalement fermé</translation>
    </message>
    <message>
        <source>Normally open</source>
        <translation>Normalement ouvert</translation>
    </message>
</context>
<context>
    <name>MoveGrafcetActionCommand</name>
    <message>
        <source>Move action %1 of %2 step %3 up</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Monter l’action %1 de l’étape %3 de %2</translation>
    </message>
    <message>
        <source>Move action %1 of %2 step %3 down</source>
        <translation>Descendre l’action %1 de l’étape %3 de %2</translation>
    </message>
</context>
<context>
    <name>MovePropertyCommand</name>
    <message>
        <source>Move property %1</source>
        <translation>Déplacer la propriété %1</translation>
    </message>
</context>
<context>
    <name>MoveVariableCommand</name>
    <message>
        <source>Move variable %1</source>
        <translation>Déplacer la variable %1</translation>
    </message>
</context>
<context>
    <name>NestedProblemText</name>
    <message>
        <source>the receptivity of T%2 of %1</source>
        <extracomment>%1: a GEMMA step; %2: the number of a transition of its nested GRAFCET</extracomment>
        <translation>la réceptivité de T%2 de %1</translation>
    </message>
    <message>
        <source>action %3 of step %2 of %1</source>
        <extracomment>%1: a GEMMA step; %2: a nested step&apos;s number; %3: the action&apos;s position in its list, from 1</extracomment>
        <translation>l&apos;action %3 de l&apos;étape %2 de %1</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is not a declared variable.</source>
        <translation>Dans %1 : « %2 » n&apos;est pas une variable déclarée.</translation>
    </message>
    <message>
        <source>In %1: a continuous action is N V or V IF &lt;condition&gt;.</source>
        <translation>Dans %1 : une action continue s&apos;écrit N V ou V IF &lt;condition&gt;.</translation>
    </message>
    <message>
        <source>In %1: a stored action is S V, R V or V := &lt;expression&gt;.</source>
        <translation>Dans %1 : une action mémorisée s&apos;écrit S V, R V ou V := &lt;expression&gt;.</translation>
    </message>
    <message>
        <source>Syntax error in %1: %2.</source>
        <translation>Erreur de syntaxe dans %1 : %2.</translation>
    </message>
    <message>
        <source>Type error in %1: %2.</source>
        <translation>Erreur de type dans %1 : %2.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is %3; this action needs a BOOL variable.</source>
        <extracomment>%3: an IEC type name (INT)</extracomment>
        <translation>Dans %1 : « %2 » est de type %3 ; cette action demande une variable BOOL.</translation>
    </message>
    <message>
        <source>In %1: %4 does not fit &apos;%2&apos; (%3): it cannot be assigned to it.</source>
        <extracomment>%2: the target variable; %3: its type; %4: the value as written</extracomment>
        <translation>Dans %1 : %4 ne convient pas à « %2 » (%3) : il ne peut pas lui être affecté.</translation>
    </message>
    <message>
        <source>In %1: %2 names step %3, which the GRAFCET of %4 does not have.</source>
        <extracomment>%2: a step activity as written (X9); %3: its step number; %4: the GEMMA step</extracomment>
        <translation>Dans %1 : %2 désigne l&apos;étape %3, que le GRAFCET de %4 n&apos;a pas.</translation>
    </message>
    <message>
        <source>In %1: %2 is longer than %3, the longest duration an IEC TIME (a TON preset) holds.</source>
        <extracomment>%2: a duration as written (25d/X1); %3: the longest IEC TIME</extracomment>
        <translation>Dans %1 : %2 dépasse %3, la plus longue durée que contient un TIME IEC (la consigne d&apos;un TON).</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; divides by zero: on the PLC an integer division or MOD by zero stops the task with a fault, and a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / 0)</extracomment>
        <translation>Dans %1 : « %2 » divise par zéro : sur l&apos;automate, une division entière ou un MOD par zéro arrête la tâche en défaut, et une division REAL donne INF ou NaN.</translation>
    </message>
    <message>
        <source>In %1: the divisor of &apos;%2&apos; can be zero: an integer division or MOD by zero stops the PLC with a fault (and the simulation), a REAL one gives INF or NaN.</source>
        <extracomment>%2: a division as written (Count / Batch)</extracomment>
        <translation>Dans %1 : le diviseur de « %2 » peut valoir zéro : une division entière ou un MOD par zéro arrête l&apos;automate en défaut (et la simulation), une division REAL donne INF ou NaN.</translation>
    </message>
    <message>
        <source>In %1: %2 is an edge on a variable that is not BOOL.</source>
        <extracomment>%2: an edge as written (RE Level)</extracomment>
        <translation>Dans %1 : %2 est un front sur une variable qui n&apos;est pas BOOL.</translation>
    </message>
    <message>
        <source>In %1: %2 is for receptivities only: an action cannot read an edge or a step duration.</source>
        <translation>Dans %1 : %2 est réservé aux réceptivités : une action ne peut lire ni un front ni une durée d&apos;étape.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is an input: it is read from the machine, actions never write it.</source>
        <translation>Dans %1 : « %2 » est une entrée : elle est lue sur la machine, les actions ne l&apos;écrivent jamais.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is %3; a continuous action needs a BOOL variable.</source>
        <extracomment>%3: an IEC type name (INT)</extracomment>
        <translation>Dans %1 : « %2 » est de type %3 ; une action continue demande une variable BOOL.</translation>
    </message>
    <message>
        <source>In %1: &apos;%2&apos; is also driven by continuous actions; a variable has either continuous or stored actions (the stored one is not generated).</source>
        <translation>Dans %1 : « %2 » est aussi commandée par des actions continues ; une variable a soit des actions continues, soit des actions mémorisées (celle-ci, mémorisée, n&apos;est pas générée).</translation>
    </message>
    <message>
        <source>In %1: invalid variable name: %2.</source>
        <translation>Dans %1 : nom de variable invalide : %2.</translation>
    </message>
    <message>
        <source>In %1: the condition reads &apos;%2&apos;, a continuous output of the same GRAFCET.</source>
        <translation>Dans %1 : la condition lit « %2 », une sortie continue du même GRAFCET.</translation>
    </message>
    <message>
        <source>The receptivity of T%2 of %1 is empty: write TRUE for a transition that is always ready.</source>
        <translation>La réceptivité de T%2 de %1 est vide : écrivez TRUE pour une transition toujours prête.</translation>
    </message>
</context>
<context>
    <name>OperatorItem</name>
    <message>
        <source>switched on</source>
        <translation>enclenché</translation>
    </message>
    <message>
        <source>switched off</source>
        <translation>déclenché</translation>
    </message>
    <message>
        <source>pressed</source>
        <translation>enfoncé</translation>
    </message>
    <message>
        <source>released</source>
        <translation>relâché</translation>
    </message>
</context>
<context>
    <name>PackMLDiagnosticText</name>
    <message>
        <source>The model has no unit mode.</source>
        <translation>Le modèle n&apos;a aucun mode d&apos;unité.</translation>
    </message>
    <message>
        <source>The initial mode %1 is not a unit mode of the model.</source>
        <translation>Le mode initial %1 n&apos;est pas un mode d&apos;unité du modèle.</translation>
    </message>
    <message>
        <source>The initial state %1 is not Stopped, Idle or Aborted.</source>
        <translation>L&apos;état initial %1 n&apos;est pas Stopped, Idle ou Aborted.</translation>
    </message>
    <message>
        <source>The model&apos;s name &apos;%1&apos; cannot name the PROGRAM (it is no IEC identifier, or the generated code or a variable takes it): the PROGRAM is named %2.</source>
        <translation>Le nom du modèle « %1 » ne peut pas nommer le PROGRAM (ce n&apos;est pas un identificateur CEI, ou le code généré ou une variable le prend) : le PROGRAM s&apos;appelle %2.</translation>
    </message>
    <message>
        <source>Unit mode %1 is outside 1..31 (PackTags UnitMode).</source>
        <translation>Le mode d&apos;unité %1 est hors de 1..31 (PackTags UnitMode).</translation>
    </message>
    <message>
        <source>Unit mode %1 is given twice.</source>
        <translation>Le mode d&apos;unité %1 est donné deux fois.</translation>
    </message>
    <message>
        <source>Unit mode %1 is named %2, not &apos;%3&apos;.</source>
        <extracomment>%2: the fixed name of a base mode (Production, Maintenance, Manual)</extracomment>
        <translation>Le mode d&apos;unité %1 s&apos;appelle %2, pas « %3 ».</translation>
    </message>
    <message>
        <source>The name &apos;%2&apos; of unit mode %1 is not an IEC identifier, and it becomes part of the names of function blocks.</source>
        <translation>Le nom « %2 » du mode d&apos;unité %1 n&apos;est pas un identificateur CEI, et il entre dans les noms des blocs fonctionnels.</translation>
    </message>
    <message>
        <source>The name &apos;%2&apos; of unit mode %1 is one the generated code uses.</source>
        <translation>Le nom « %2 » du mode d&apos;unité %1 est utilisé par le code généré.</translation>
    </message>
    <message>
        <source>Unit mode %1 is named &apos;%2&apos;, as mode %3 is (ignoring case).</source>
        <translation>Le mode d&apos;unité %1 s&apos;appelle « %2 », comme le mode %3 (sans tenir compte de la casse).</translation>
    </message>
    <message>
        <source>Mode %1 lists %2 as disabled, which every unit needs: ignored.</source>
        <translation>Le mode %1 désactive %2, dont toute unité a besoin : ignoré.</translation>
    </message>
    <message>
        <source>Mode %1 lists %2 as disabled, but it stays enabled while %3 is enabled.</source>
        <extracomment>%3: the enabled acting states of the loop (Holding, Unholding)</extracomment>
        <translation>Le mode %1 désactive %2, mais cet état reste activé tant que %3 est activé.</translation>
    </message>
    <message>
        <source>Mode %1 allows a mode change in %2, an acting state, half-way through its GRAFCET: ignored.</source>
        <translation>Le mode %1 autorise un changement de mode dans %2, un état actif, au milieu de son GRAFCET : ignoré.</translation>
    </message>
    <message>
        <source>Mode %1 allows a mode change in %2, which it disables: no effect.</source>
        <translation>Le mode %1 autorise un changement de mode dans %2, qu&apos;il désactive : sans effet.</translation>
    </message>
    <message>
        <source>Mode %1 can never be current: it is not the initial mode, and no state allows a change into it from another mode.</source>
        <translation>Le mode %1 ne peut jamais être courant : ce n&apos;est pas le mode initial, et aucun état ne permet d&apos;y passer depuis un autre mode.</translation>
    </message>
    <message>
        <source>In mode %1, no sequence of transitions leads to Execute from where the mode begins (counting a State Complete only where the state&apos;s GRAFCET writes Complete).</source>
        <translation>Dans le mode %1, aucune suite de transitions ne mène à Execute depuis là où le mode commence (un State Complete ne compte que là où le GRAFCET de l&apos;état écrit Complete).</translation>
    </message>
    <message>
        <source>In mode %1, no sequence of transitions reaches %2 from where the mode begins: it is never active.</source>
        <translation>Dans le mode %1, aucune suite de transitions n&apos;atteint %2 depuis là où le mode commence : l&apos;état n&apos;est jamais actif.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: Aborting never writes Complete: nothing leaves Aborting, so the unit can never reach Aborted.</source>
        <translation>Le GRAFCET de %1 : Aborting n&apos;écrit jamais Complete : rien ne fait sortir d&apos;Aborting, l&apos;unité ne peut donc jamais atteindre Aborted.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: %2 never writes Complete: only Stop or Abort leave the state.</source>
        <translation>Le GRAFCET de %1 : %2 n&apos;écrit jamais Complete : seuls Stop ou Abort font sortir de l&apos;état.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: %2 is kept, but the mode disables the state: it generates no code.</source>
        <translation>Le GRAFCET de %1 : %2 est conservé, mais le mode désactive l&apos;état : il ne génère aucun code.</translation>
    </message>
    <message>
        <source>there is no mode %1</source>
        <translation>il n&apos;y a pas de mode %1</translation>
    </message>
    <message>
        <source>that is the mode itself</source>
        <translation>c&apos;est le mode lui-même</translation>
    </message>
    <message>
        <source>mode %1 has no GRAFCET of its own there</source>
        <translation>le mode %1 n&apos;y a pas de GRAFCET propre</translation>
    </message>
    <message>
        <source>%1: %2 runs the same GRAFCET as mode %3, but %4.</source>
        <extracomment>%4: why (there is no mode 9, that is the mode itself, ...)</extracomment>
        <translation>%1 : %2 exécute le même GRAFCET que le mode %3, mais %4.</translation>
    </message>
    <message>
        <source>The GRAFCET of %1: Execute writes Complete, which nothing reads in the 2022 edition: use the Complete command.</source>
        <translation>Le GRAFCET de %1 : Execute écrit Complete, que rien ne lit dans l&apos;édition 2022 : utilisez la commande Complete.</translation>
    </message>
    <message>
        <source>The condition of %1 is empty: write FALSE for a command that comes only through CntrlCmd.</source>
        <translation>La condition de %1 est vide : écrivez FALSE pour une commande qui ne vient que par CntrlCmd.</translation>
    </message>
    <message>
        <source>Command %2 has the same condition as command %1: one rising edge issues both, and only the first in priority acts.</source>
        <translation>La commande %2 a la même condition que la commande %1 : un même front montant émet les deux, et seule la première en priorité agit.</translation>
    </message>
    <message>
        <source>The request of mode %2 has the same condition as the request of mode %1: one rising edge issues both, and only the first in priority acts.</source>
        <translation>La demande du mode %2 a la même condition que la demande du mode %1 : un même front montant émet les deux, et seule la première en priorité agit.</translation>
    </message>
    <message>
        <source>The condition of %1 reads the output &apos;%2&apos;: commands and mode requests come from an operator, a line controller or an alarm, so read an input or an internal variable.</source>
        <translation>La condition de %1 lit la sortie « %2 » : commandes et demandes de mode viennent d&apos;un opérateur, d&apos;un contrôleur de ligne ou d&apos;une alarme, lisez donc une entrée ou une variable interne.</translation>
    </message>
    <message>
        <source>No enabled state of any mode accepts the command %1: it generates no code.</source>
        <translation>Aucun état activé d&apos;aucun mode n&apos;accepte la commande %1 : elle ne génère aucun code.</translation>
    </message>
    <message>
        <source>The Complete command exists in the 2022 edition only: its setting is ignored in this 2015 model.</source>
        <translation>La commande Complete n&apos;existe que dans l&apos;édition 2022 : son réglage est ignoré dans ce modèle 2015.</translation>
    </message>
    <message>
        <source>The option completeInSuspendedHeld is for the 2022 edition only: it is ignored in this 2015 model.</source>
        <translation>L&apos;option completeInSuspendedHeld n&apos;est que pour l&apos;édition 2022 : elle est ignorée dans ce modèle 2015.</translation>
    </message>
    <message>
        <source>a step activity</source>
        <translation>une activité d&apos;étape</translation>
    </message>
    <message>
        <source>a step duration</source>
        <translation>une durée d&apos;étape</translation>
    </message>
    <message>
        <source>an edge</source>
        <translation>un front</translation>
    </message>
    <message>
        <source>The condition of %1 uses %2 (&apos;%3&apos;), which only the texts of nested GRAFCETs have; a command or request is already the rising edge of its condition.</source>
        <extracomment>%2: what the condition uses (a step activity, an edge...); %3: the text as written</extracomment>
        <translation>La condition de %1 utilise %2 (« %3 »), que seuls les textes des GRAFCET imbriqués ont ; une commande ou une demande est déjà le front montant de sa condition.</translation>
    </message>
    <message>
        <source>mode %1</source>
        <extracomment>A unit mode of a PackML model: &quot;mode Manual&quot;</extracomment>
        <translation>mode %1</translation>
    </message>
    <message>
        <source>command %1</source>
        <extracomment>A PackML command: &quot;command Hold&quot;</extracomment>
        <translation>commande %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>A state in a unit mode: &quot;Manual: Execute&quot;</extracomment>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>request of mode %1</source>
        <extracomment>The request condition of a unit mode</extracomment>
        <translation>demande du mode %1</translation>
    </message>
    <message>
        <source>The variable name &apos;%1&apos; is one the generated PackML code uses (PackTags, the state machine, the function blocks or the program %2).</source>
        <translation>Le nom de variable « %1 » est utilisé par le code PackML généré (PackTags, la machine d&apos;états, les blocs fonctionnels ou le programme %2).</translation>
    </message>
</context>
<context>
    <name>PackmlChartExport</name>
    <message>
        <source>PackML chart drawn by GG Studio</source>
        <translation>Diagramme PackML dessiné par GG Studio</translation>
    </message>
    <message>
        <source>Unit mode %1</source>
        <translation>Mode d&apos;unité %1</translation>
    </message>
</context>
<context>
    <name>PackmlSimulationText</name>
    <message>
        <source>%1 cannot be entered in %2: %3</source>
        <extracomment>%1: a unit mode (Manual), %2: a PackML state (Execute), %3: why</extracomment>
        <translation>%1 ne peut pas être activé dans %2 : %3</translation>
    </message>
    <message>
        <source>%1; %2 grants it in no state</source>
        <extracomment>%1: a refusal, %2: the current unit mode</extracomment>
        <translation>%1 ; %2 ne l&apos;accorde dans aucun état</translation>
    </message>
    <message>
        <source>%1; it can be entered in %2</source>
        <extracomment>%1: a refusal, %2: PackML states (&quot;Stopped, Idle, Aborted&quot;)</extracomment>
        <translation>%1 ; il peut être activé dans %2</translation>
    </message>
    <message>
        <source>%1 allows no mode change there</source>
        <translation>%1 n&apos;y autorise aucun changement de mode</translation>
    </message>
    <message>
        <source>%1 disables this state</source>
        <translation>%1 désactive cet état</translation>
    </message>
    <message>
        <source>%1 is not granted: %2, lower-numbered, is granted in the same scan</source>
        <extracomment>%2: the unit mode granted instead</extracomment>
        <translation>%1 n&apos;est pas accordé : %2, de numéro inférieur, est accordé dans le même cycle</translation>
    </message>
    <message>
        <source>%1 is requested: it is already the current mode</source>
        <translation>%1 est demandé : c&apos;est déjà le mode courant</translation>
    </message>
    <message>
        <source>%1 names no unit mode</source>
        <translation>%1 ne désigne aucun mode de l&apos;unité</translation>
    </message>
    <message>
        <source>the SC of %1</source>
        <translation>le SC de %1</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2</source>
        <extracomment>%1: a PackML command (Hold), %2: a state (Idle)</extracomment>
        <translation>%1 n&apos;est pas accepté dans %2</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2 in %3: the mode disables where it leads</source>
        <extracomment>%1: a command, %2: a state, %3: a unit mode</extracomment>
        <translation>%1 n&apos;est pas accepté dans %2 en %3 : le mode désactive l&apos;état où il mène</translation>
    </message>
    <message>
        <source>%1 is pre-empted by %2</source>
        <extracomment>%2: the transition that fired instead (&quot;Execute-Stop-&gt;Stopped&quot;)</extracomment>
        <translation>%1 est devancé par %2</translation>
    </message>
    <message>
        <source>%1 names no command</source>
        <translation>%1 ne désigne aucune commande</translation>
    </message>
    <message>
        <source>the receptivity of T%1 of %2</source>
        <extracomment>%1: a transition number of a nested GRAFCET, %2: its function block instance</extracomment>
        <translation>la réceptivité de T%1 de %2</translation>
    </message>
    <message>
        <source>action %1 of step %2 of %3</source>
        <extracomment>%1: an action&apos;s position, %2: a step number, %3: a function block instance</extracomment>
        <translation>l&apos;action %1 de l&apos;étape %2 de %3</translation>
    </message>
    <message>
        <source>the condition of the %1 command</source>
        <extracomment>%1: a PackML command (Start)</extracomment>
        <translation>la condition de la commande %1</translation>
    </message>
    <message>
        <source>the request condition of mode %1</source>
        <extracomment>%1: a unit mode (Manual)</extracomment>
        <translation>la condition de demande du mode %1</translation>
    </message>
    <message>
        <source>cannot set %1: %2</source>
        <extracomment>%1: a variable or instance, %2: why (from the simulator)</extracomment>
        <translation>impossible d&apos;affecter %1 : %2</translation>
    </message>
    <message>
        <source>expected state %1, the state is %2</source>
        <translation>état attendu %1, l&apos;état est %2</translation>
    </message>
    <message>
        <source>expected mode %1, the mode is %2</source>
        <translation>mode attendu %1, le mode est %2</translation>
    </message>
    <message>
        <source>expected %1 = %2, it is %3</source>
        <translation>attendu %1 = %2, la valeur est %3</translation>
    </message>
    <message>
        <source>expected %1 to fire, no transition fired</source>
        <translation>franchissement attendu de %1, aucune transition franchie</translation>
    </message>
    <message>
        <source>expected %1 to fire, %2 fired</source>
        <translation>franchissement attendu de %1, %2 franchie</translation>
    </message>
    <message>
        <source>expected no transition to fire, %1 fired</source>
        <translation>aucun franchissement attendu, %1 franchie</translation>
    </message>
    <message>
        <source>scan %1: %2</source>
        <extracomment>%1: a scan number, %2: what did not hold</extracomment>
        <translation>cycle %1 : %2</translation>
    </message>
    <message>
        <source>Stopped at scan %1: integer division by zero in %2 (%3 in &apos;%4&apos;). On the PLC the task stops with a fault; Reset to run again.</source>
        <extracomment>%1: a scan number, %2: where (a condition, a receptivity, an action), %3: the division as written, %4: the text</extracomment>
        <translation>Arrêté au cycle %1 : division entière par zéro dans %2 (%3 dans « %4 »). Sur l&apos;automate, la tâche s&apos;arrête en défaut ; réinitialisez pour relancer.</translation>
    </message>
    <message>
        <source>%1: granted</source>
        <extracomment>a unit mode request that the mode manager granted</extracomment>
        <translation>%1 : accordé</translation>
    </message>
    <message>
        <source>%1: not granted</source>
        <translation>%1 : non accordé</translation>
    </message>
    <message>
        <source>%1: fired %2</source>
        <extracomment>%1: a command, %2: the transition it fired (&quot;Idle-Start-&gt;Execute&quot;)</extracomment>
        <translation>%1 : %2 franchie</translation>
    </message>
    <message>
        <source>%1: no transition fired</source>
        <translation>%1 : aucune transition franchie</translation>
    </message>
</context>
<context>
    <name>PackmlTexts</name>
    <message>
        <source>Wait state</source>
        <translation>État d&apos;attente</translation>
    </message>
    <message>
        <source>Acting state</source>
        <translation>État actif</translation>
    </message>
    <message>
        <source>Dual state: acts and waits for a command</source>
        <translation>État double : agit et attend une commande</translation>
    </message>
    <message>
        <source>Clears the faults that led to Aborted, then goes to Stopped.</source>
        <translation>Efface les défauts qui ont mené à Aborted, puis passe à Stopped.</translation>
    </message>
    <message>
        <source>Powered and stationary; waits for Reset.</source>
        <translation>Sous tension et à l&apos;arrêt ; attend Reset.</translation>
    </message>
    <message>
        <source>Prepares the unit to produce, then goes to Execute.</source>
        <translation>Prépare l&apos;unité à produire, puis passe à Execute.</translation>
    </message>
    <message>
        <source>Reset and ready; waits for Start.</source>
        <translation>Réinitialisée et prête ; attend Start.</translation>
    </message>
    <message>
        <source>Paused by a condition outside the unit (starved, blocked); waits for Unsuspend.</source>
        <translation>En pause pour une condition extérieure à l&apos;unité (manque, bourrage aval) ; attend Unsuspend.</translation>
    </message>
    <message>
        <source>Produces; waits for Hold, Suspend or the end of the batch.</source>
        <translation>Produit ; attend Hold, Suspend ou la fin du lot.</translation>
    </message>
    <message>
        <source>Brings the unit to a controlled stop, then goes to Stopped.</source>
        <translation>Amène l&apos;unité à un arrêt contrôlé, puis passe à Stopped.</translation>
    </message>
    <message>
        <source>Brings the unit to a quick safe stop, then goes to Aborted.</source>
        <translation>Amène l&apos;unité à un arrêt rapide et sûr, puis passe à Aborted.</translation>
    </message>
    <message>
        <source>Stopped after an abort; waits for Clear.</source>
        <translation>Arrêtée après un abandon ; attend Clear.</translation>
    </message>
    <message>
        <source>Brings production to a controlled pause for an internal reason, then goes to Held.</source>
        <translation>Met la production en pause contrôlée pour une raison interne, puis passe à Held.</translation>
    </message>
    <message>
        <source>Paused for an internal reason; waits for Unhold.</source>
        <translation>En pause pour une raison interne ; attend Unhold.</translation>
    </message>
    <message>
        <source>Prepares to resume production after Held, then goes to Execute.</source>
        <translation>Prépare la reprise de la production après Held, puis passe à Execute.</translation>
    </message>
    <message>
        <source>Brings production to a controlled pause for an outside reason, then goes to Suspended.</source>
        <translation>Met la production en pause contrôlée pour une raison extérieure, puis passe à Suspended.</translation>
    </message>
    <message>
        <source>Prepares to resume production after Suspended, then goes to Execute.</source>
        <translation>Prépare la reprise de la production après Suspended, puis passe à Execute.</translation>
    </message>
    <message>
        <source>Brings the unit to its ready state, then goes to Idle.</source>
        <translation>Amène l&apos;unité dans son état prêt, puis passe à Idle.</translation>
    </message>
    <message>
        <source>Ends the batch in order, then goes to Complete.</source>
        <translation>Termine le lot en ordre, puis passe à Complete.</translation>
    </message>
    <message>
        <source>The batch is complete; waits for Reset.</source>
        <translation>Le lot est terminé ; attend Reset.</translation>
    </message>
    <message>
        <source>Reset: make the unit ready to start again.</source>
        <translation>Reset : rendre l&apos;unité prête à redémarrer.</translation>
    </message>
    <message>
        <source>Start: begin producing.</source>
        <translation>Start : commencer à produire.</translation>
    </message>
    <message>
        <source>Stop: bring the unit to a controlled stop.</source>
        <translation>Stop : amener l&apos;unité à un arrêt contrôlé.</translation>
    </message>
    <message>
        <source>Hold: pause production for an internal reason.</source>
        <translation>Hold : mettre la production en pause pour une raison interne.</translation>
    </message>
    <message>
        <source>Unhold: resume production after a Hold.</source>
        <translation>Unhold : reprendre la production après un Hold.</translation>
    </message>
    <message>
        <source>Suspend: pause production for an outside reason.</source>
        <translation>Suspend : mettre la production en pause pour une raison extérieure.</translation>
    </message>
    <message>
        <source>Unsuspend: resume production after a Suspend.</source>
        <translation>Unsuspend : reprendre la production après un Suspend.</translation>
    </message>
    <message>
        <source>Abort: stop the unit at once, safely.</source>
        <translation>Abort : arrêter l&apos;unité immédiatement, en sécurité.</translation>
    </message>
    <message>
        <source>Clear: clear the faults after an Abort.</source>
        <translation>Clear : effacer les défauts après un Abort.</translation>
    </message>
    <message>
        <source>Complete: end the batch.</source>
        <translation>Complete : terminer le lot.</translation>
    </message>
</context>
<context>
    <name>PackmlVerificationText</name>
    <message>
        <source>In %1, Execute, entered again from the Hold or Suspend loop, started afresh instead of resuming where it was paused.</source>
        <translation>Dans %1, Execute, réactivé depuis la boucle Hold ou Suspend, est reparti de zéro au lieu de reprendre là où il avait été interrompu.</translation>
    </message>
    <message>
        <source>In %1, Execute resumed where it should have started afresh from its initial situation.</source>
        <translation>Dans %1, Execute a repris là où il aurait dû repartir de sa situation initiale.</translation>
    </message>
    <message>
        <source>In %1, Execute resumed in a situation other than the one it was paused in.</source>
        <translation>Dans %1, Execute a repris dans une autre situation que celle où il avait été interrompu.</translation>
    </message>
    <message>
        <source>The verification was not exhaustive (its time or size limit, timers or numeric inputs it explores only in part): stuck states, states never active and commands never accepted were not decided, and the absence of other findings is not a proof.</source>
        <translation>La vérification n&apos;a pas été exhaustive (sa limite de temps ou de taille, des temporisations ou des entrées numériques qu&apos;elle n&apos;explore qu&apos;en partie) : les états bloqués, les états jamais actifs et les commandes jamais acceptées n&apos;ont pas été décidés, et l&apos;absence d&apos;autres constats n&apos;est pas une preuve.</translation>
    </message>
    <message>
        <source>In %1, the GRAFCET of %2 can reach a situation from which Complete never becomes TRUE: only Stop or Abort then leave %2.</source>
        <translation>Dans %1, le GRAFCET de %2 peut atteindre une situation d&apos;où Complete ne devient jamais TRUE : seuls Stop ou Abort font alors quitter %2.</translation>
    </message>
    <message>
        <source>In %1, Aborting can reach a situation from which Aborted is never reached: nothing leaves it.</source>
        <translation>Dans %1, Aborting peut atteindre une situation d&apos;où Aborted n&apos;est jamais atteint : rien ne permet d&apos;en sortir.</translation>
    </message>
    <message>
        <source>%2 was active at the end of a scan in %1, a mode that disables it.</source>
        <translation>%2 était actif à la fin d&apos;un cycle dans %1, un mode qui le désactive.</translation>
    </message>
    <message>
        <source>The mode changed from %1 in %2, a state where this change is not allowed.</source>
        <translation>Le mode a changé depuis %1 dans %2, un état où ce changement n&apos;est pas permis.</translation>
    </message>
    <message>
        <source>%1 is never the current mode.</source>
        <translation>%1 n&apos;est jamais le mode courant.</translation>
    </message>
    <message>
        <source>%2 is enabled in %1 but never active there.</source>
        <translation>%2 est activé dans %1 mais n&apos;y est jamais actif.</translation>
    </message>
    <message>
        <source>The %1 command is accepted in no reachable configuration.</source>
        <translation>La commande %1 n&apos;est acceptée dans aucune configuration atteignable.</translation>
    </message>
    <message>
        <source>In %1, continuous outputs are TRUE at the end of the scan that enters %2: %3.</source>
        <translation>Dans %1, des sorties continues sont TRUE à la fin du cycle qui entre dans %2 : %3.</translation>
    </message>
    <message>
        <source>In %1, stored outputs can still be TRUE when %2 is entered: %3.</source>
        <translation>Dans %1, des sorties mémorisées peuvent encore être TRUE à l&apos;entrée dans %2 : %3.</translation>
    </message>
    <message>
        <source>Stuck states were not decided in %1: timers longer than one cycle may or may not have elapsed, and the ways to Complete found there let timers elapse in an order the PLC&apos;s may not. Every other finding is decided.</source>
        <translation>Les états bloqués n&apos;ont pas été décidés dans %1 : les temporisations plus longues qu&apos;un cycle peuvent être écoulées ou non, et les chemins vers Complete trouvés là laissent les temporisations s&apos;écouler dans un ordre que celles de l&apos;automate peuvent ne pas suivre. Toutes les autres constatations sont décidées.</translation>
    </message>
</context>
<context>
    <name>PartSourceItem</name>
    <message>
        <source>Unlimited parts</source>
        <translation>Pièces illimitées</translation>
    </message>
    <message>
        <source>Parts left: %1</source>
        <translation>Pièces restantes : %1</translation>
    </message>
    <message>
        <source>feeds no conveyor</source>
        <translation>n&apos;alimente aucun convoyeur</translation>
    </message>
    <message>
        <source>feeds %1</source>
        <translation>alimente %1</translation>
    </message>
</context>
<context>
    <name>PasteVariablesCommand</name>
    <message>
        <source>Paste variable %1</source>
        <translation>Coller la variable %1</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n variables</source>
        <translation>
            <numerusform>Coller %n variable</numerusform>
            <numerusform>Coller %n variables</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PictureFile</name>
    <message>
        <source>The SVG picture could not be drawn.</source>
        <translation>L&apos;image SVG n&apos;a pas pu être dessinée.</translation>
    </message>
    <message>
        <source>Not enough memory for a picture of %1 × %2 pixels.</source>
        <translation>Mémoire insuffisante pour une image de %1 × %2 pixels.</translation>
    </message>
    <message>
        <source>The PNG picture could not be encoded.</source>
        <translation>L&apos;image PNG n&apos;a pas pu être encodée.</translation>
    </message>
    <message>
        <source>The PDF document could not be drawn.</source>
        <translation>Le document PDF n&apos;a pas pu être dessiné.</translation>
    </message>
</context>
<context>
    <name>PropertyProblemText</name>
    <message>
        <source>&apos;%1&apos; is not a declared variable</source>
        <translation>«&#xa0;%1&#xa0;» n&apos;est pas une variable déclarée</translation>
    </message>
    <message>
        <source>there is no visible GEMMA step &apos;%1&apos;</source>
        <translation>il n&apos;y a pas d&apos;étape GEMMA visible «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <source>the step %1 has no nested GRAFCET</source>
        <translation>l&apos;étape %1 n&apos;a pas de GRAFCET imbriqué</translation>
    </message>
    <message>
        <source>the GRAFCET of %1 has no step %2</source>
        <translation>le GRAFCET de %1 n&apos;a pas d&apos;étape %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is only defined when verifying with single faults (Simulation &gt; Verify with Single Faults, with the machine)</source>
        <translation>&apos;%1&apos; n&apos;est défini que lors d&apos;une vérification avec des défauts uniques (Simulation &gt; Vérifier avec des défauts uniques, avec la machine)</translation>
    </message>
</context>
<context>
    <name>RecoveryPrompt</name>
    <message>
        <source>an untitled model</source>
        <translation>un modèle sans titre</translation>
    </message>
    <message>
        <source>Discard Unsaved Changes</source>
        <translation>Abandonner les modifications non enregistrées</translation>
    </message>
    <message>
        <source>Delete the autosaved copy of %1 for good?</source>
        <translation>Supprimer définitivement la copie enregistrée automatiquement de %1&#xa0;?</translation>
    </message>
    <message>
        <source>The changes it holds cannot be recovered afterwards.</source>
        <translation>Les modifications qu&apos;elle contient ne pourront plus être récupérées.</translation>
    </message>
    <message>
        <source>Delete Copy</source>
        <translation>Supprimer la copie</translation>
    </message>
    <message>
        <source>&amp;Keep Copy</source>
        <translation>&amp;Garder la copie</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Récupérer les modifications non enregistrées</translation>
    </message>
    <message>
        <source>GG Studio ended without saving %1.</source>
        <translation>GG Studio s&apos;est arrêté sans enregistrer %1.</translation>
    </message>
    <message>
        <source>Autosave kept a copy on %1. Recover it? You can then save it or discard it.</source>
        <translation>L&apos;enregistrement automatique en a conservé une copie le %1. La récupérer&#xa0;? Vous pourrez ensuite l&apos;enregistrer ou l&apos;abandonner.</translation>
    </message>
    <message>
        <source>The original file can no longer be identified (moved, deleted or changed since, or named by an older version): saving the recovered model will ask for a file.</source>
        <translation>Le fichier d&apos;origine ne peut plus être identifié (déplacé, supprimé ou modifié depuis, ou nommé par une version antérieure)&#xa0;: l&apos;enregistrement du modèle récupéré demandera un fichier.</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Récupérer</translation>
    </message>
    <message>
        <source>Discard…</source>
        <translation>Abandonner…</translation>
    </message>
    <message>
        <source>&amp;Not Now</source>
        <translation>&amp;Plus tard</translation>
    </message>
    <message>
        <source>The autosaved copy could not be read.</source>
        <translation>La copie enregistrée automatiquement n&apos;a pas pu être lue.</translation>
    </message>
</context>
<context>
    <name>RemoveGrafcetActionCommand</name>
    <message>
        <source>Remove action %1 of %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Supprimer l’action %1 de l’étape %3 de %2</translation>
    </message>
</context>
<context>
    <name>RemoveMachineComponentCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>Supprimer %1</translation>
    </message>
</context>
<context>
    <name>RemoveModeCommand</name>
    <message>
        <source>Remove mode %1</source>
        <translation>Supprimer le mode %1</translation>
    </message>
</context>
<context>
    <name>RemovePropertyCommand</name>
    <message>
        <source>Remove property %1</source>
        <translation>Supprimer la propriété %1</translation>
    </message>
</context>
<context>
    <name>RemoveVariableCommand</name>
    <message>
        <source>Remove variable %1</source>
        <translation>Supprimer la variable %1</translation>
    </message>
</context>
<context>
    <name>RenameModeCommand</name>
    <message>
        <source>Rename mode %1</source>
        <translation>Renommer le mode %1</translation>
    </message>
</context>
<context>
    <name>RenameVariableCommand</name>
    <message>
        <source>Rename variable %1 to %2</source>
        <translation>Renommer la variable %1 en %2</translation>
    </message>
    <message>
        <source>a variable named &apos;%1&apos; already exists (IEC names ignore case)</source>
        <translation>une variable nommée «&#xa0;%1&#xa0;» existe déjà (les noms IEC ignorent la casse)</translation>
    </message>
</context>
<context>
    <name>RenumberGrafcetStepCommand</name>
    <message>
        <source>Renumber %1 step %2 to %3</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET, %3 its new number</extracomment>
        <translation>Renuméroter l’étape %2 de %1 en %3</translation>
    </message>
</context>
<context>
    <name>ResetModelCommand</name>
    <message>
        <source>Reset to template</source>
        <translation>Réinitialiser au gabarit</translation>
    </message>
</context>
<context>
    <name>SetCommandCommentCommand</name>
    <message>
        <source>Edit comment of command %1</source>
        <translation>Modifier le commentaire de la commande %1</translation>
    </message>
</context>
<context>
    <name>SetCommandConditionCommand</name>
    <message>
        <source>Edit condition of command %1</source>
        <translation>Modifier la condition de la commande %1</translation>
    </message>
</context>
<context>
    <name>SetConditionCommand</name>
    <message>
        <source>Edit condition of %1</source>
        <translation>Modifier la réceptivité de %1</translation>
    </message>
</context>
<context>
    <name>SetCycleTimeCommand</name>
    <message>
        <source>Set cycle time to %1 ms</source>
        <translation>Régler le temps de cycle à %1 ms</translation>
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
        <translation>Choisir le dialecte %1</translation>
    </message>
</context>
<context>
    <name>SetElementsHiddenCommand</name>
    <message numerus="yes">
        <source>Hide %n element(s)</source>
        <translation>
            <numerusform>Masquer %n élément</numerusform>
            <numerusform>Masquer %n éléments</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show %n element(s)</source>
        <translation>
            <numerusform>Afficher %n élément</numerusform>
            <numerusform>Afficher %n éléments</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SetEvolutionRuleCommand</name>
    <message>
        <source>Set evolution rule to until stable</source>
        <translation>Changer la règle d&apos;évolution en «&#xa0;jusqu&apos;à stabilité&#xa0;»</translation>
    </message>
    <message>
        <source>Set evolution rule to one evolution per scan</source>
        <translation>Changer la règle d&apos;évolution en «&#xa0;une évolution par cycle&#xa0;»</translation>
    </message>
</context>
<context>
    <name>SetGrafcetActionCommand</name>
    <message>
        <source>Set action %1 of %2 step %3</source>
        <extracomment>%1 is the action&apos;s place in the list (from 1), %2 the GEMMA step, %3 the nested step number</extracomment>
        <translation>Modifier l’action %1 de l’étape %3 de %2</translation>
    </message>
</context>
<context>
    <name>SetGrafcetChoiceCommand</name>
    <message>
        <source>Give %1 its own GRAFCET in mode %2</source>
        <translation>Donner à %1 son propre GRAFCET dans le mode %2</translation>
    </message>
    <message>
        <source>Run in %1 of mode %2 the GRAFCET of mode %3</source>
        <translation>Exécuter dans %1 du mode %2 le GRAFCET du mode %3</translation>
    </message>
    <message>
        <source>Remove the GRAFCET of %1 in mode %2</source>
        <translation>Supprimer le GRAFCET de %1 dans le mode %2</translation>
    </message>
</context>
<context>
    <name>SetGrafcetStepCommentCommand</name>
    <message>
        <source>Edit comment of %1 step %2</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET: &quot;Edit comment of F1 step 3&quot;</extracomment>
        <translation>Modifier le commentaire de l’étape %2 de %1</translation>
    </message>
</context>
<context>
    <name>SetGrafcetStepInitialCommand</name>
    <message>
        <source>Make %1 step %2 initial</source>
        <extracomment>%1 is the GEMMA step, %2 a step number of its nested GRAFCET</extracomment>
        <translation>Rendre initiale l’étape %2 de %1</translation>
    </message>
    <message>
        <source>Make %1 step %2 not initial</source>
        <translation>Rendre non initiale l’étape %2 de %1</translation>
    </message>
</context>
<context>
    <name>SetInitialStepCommand</name>
    <message>
        <source>Make %1 the initial step</source>
        <translation>Faire de %1 l&apos;étape initiale</translation>
    </message>
</context>
<context>
    <name>SetModeCommentCommand</name>
    <message>
        <source>Edit comment of mode %1</source>
        <translation>Modifier le commentaire du mode %1</translation>
    </message>
</context>
<context>
    <name>SetModeRequestCommand</name>
    <message>
        <source>Edit request condition of mode %1</source>
        <translation>Modifier la condition de demande du mode %1</translation>
    </message>
</context>
<context>
    <name>SetModeStatesCommand</name>
    <message>
        <source>Change disabled states of mode %1</source>
        <translation>Modifier les états désactivés du mode %1</translation>
    </message>
    <message>
        <source>Change mode-change states of mode %1</source>
        <translation>Modifier les états de changement de mode du mode %1</translation>
    </message>
</context>
<context>
    <name>SetModelNameCommand</name>
    <message>
        <source>Rename model</source>
        <translation>Renommer le modèle</translation>
    </message>
</context>
<context>
    <name>SetNegatedCommand</name>
    <message>
        <source>Negate %1</source>
        <translation>Nier %1</translation>
    </message>
    <message>
        <source>Remove negation of %1</source>
        <translation>Retirer la négation de %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlInitialModeCommand</name>
    <message>
        <source>Set initial mode to %1</source>
        <translation>Définir le mode initial à %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlInitialStateCommand</name>
    <message>
        <source>Set initial state to %1</source>
        <translation>Définir l&apos;état initial à %1</translation>
    </message>
</context>
<context>
    <name>SetPackmlOptionsCommand</name>
    <message>
        <source>Change PackML edition and options</source>
        <translation>Modifier l&apos;édition et les options PackML</translation>
    </message>
</context>
<context>
    <name>SetPriorityCommand</name>
    <message>
        <source>Set priority of %1 to %2</source>
        <translation>Régler la priorité de %1 à %2</translation>
    </message>
</context>
<context>
    <name>SetPropertyCommentCommand</name>
    <message>
        <source>Edit comment of property %1</source>
        <translation>Modifier le commentaire de la propriété %1</translation>
    </message>
</context>
<context>
    <name>SetPropertyTextCommand</name>
    <message>
        <source>Edit property %1</source>
        <translation>Modifier la propriété %1</translation>
    </message>
</context>
<context>
    <name>SetReceptivityCommand</name>
    <message>
        <source>Set receptivity of %1 T%2</source>
        <extracomment>%1 is the GEMMA step, %2 the transition number of its nested GRAFCET: &quot;Set receptivity of F1 T3&quot;</extracomment>
        <translation>Modifier la réceptivité de %1 T%2</translation>
    </message>
</context>
<context>
    <name>SetStepCommentCommand</name>
    <message>
        <source>Edit comment of %1</source>
        <translation>Modifier le commentaire de %1</translation>
    </message>
</context>
<context>
    <name>SetStepHiddenCommand</name>
    <message>
        <source>Hide step %1</source>
        <translation>Masquer l&apos;étape %1</translation>
    </message>
    <message>
        <source>Show step %1</source>
        <translation>Afficher l&apos;étape %1</translation>
    </message>
</context>
<context>
    <name>SetStepTypeCommand</name>
    <message>
        <source>macro-step</source>
        <translation>macro-étape</translation>
    </message>
    <message>
        <source>enclosing step</source>
        <translation>étape encapsulante</translation>
    </message>
    <message>
        <source>simple step</source>
        <translation>étape simple</translation>
    </message>
    <message>
        <source>Set %1 to %2</source>
        <translation>Changer %1 en %2</translation>
    </message>
</context>
<context>
    <name>SetTokensCommand</name>
    <message>
        <source>Set tokens of %1</source>
        <translation>Définir les mémoires de %1</translation>
    </message>
</context>
<context>
    <name>SetTransitionHiddenCommand</name>
    <message>
        <source>Hide transition %1</source>
        <translation>Masquer la transition %1</translation>
    </message>
    <message>
        <source>Show transition %1</source>
        <translation>Afficher la transition %1</translation>
    </message>
</context>
<context>
    <name>SetVariableCommentCommand</name>
    <message>
        <source>Edit comment of %1</source>
        <translation>Modifier le commentaire de %1</translation>
    </message>
</context>
<context>
    <name>SetVariableDefaultCommand</name>
    <message>
        <source>Set default of %1</source>
        <translation>Modifier la valeur initiale de %1</translation>
    </message>
</context>
<context>
    <name>SetVariableKindCommand</name>
    <message>
        <source>Set kind of %1 to output</source>
        <translation>Changer la nature de %1 en sortie</translation>
    </message>
    <message>
        <source>Set kind of %1 to internal</source>
        <translation>Changer la nature de %1 en interne</translation>
    </message>
    <message>
        <source>Set kind of %1 to input</source>
        <translation>Changer la nature de %1 en entrée</translation>
    </message>
</context>
<context>
    <name>SetVariableTypeCommand</name>
    <message>
        <source>Set type of %1 to %2</source>
        <translation>Changer le type de %1 en %2</translation>
    </message>
</context>
<context>
    <name>SimulationText</name>
    <message>
        <source>%1 = %2 (token of %3)</source>
        <extracomment>a token variable, its value, then the literal it stores (&quot;NOT Stop&quot;)</extracomment>
        <translation>%1 = %2 (mémoire de %3)</translation>
    </message>
    <message>
        <source>%1 is %2</source>
        <extracomment>an IEC expression of a condition, then TRUE or FALSE</extracomment>
        <translation>%1 est %2</translation>
    </message>
    <message>
        <source>%1 is %2 (%3)</source>
        <extracomment>an IEC expression of a condition, TRUE or FALSE, then the values it reads (&quot;Speed = 3&quot;)</extracomment>
        <translation>%1 est %2 (%3)</translation>
    </message>
    <message>
        <source>The condition cannot be used: it is FALSE.</source>
        <translation>La réceptivité est inutilisable&#xa0;: elle vaut FALSE.</translation>
    </message>
    <message>
        <source>cannot apply: %1</source>
        <extracomment>%1: why, from the simulator (English)</extracomment>
        <translation>impossible d&apos;appliquer&#xa0;: %1</translation>
    </message>
    <message>
        <source>expected step %1, active step is %2</source>
        <translation>étape %1 attendue, l&apos;étape active est %2</translation>
    </message>
    <message>
        <source>expected step %1, no visible step is active (State = %2)</source>
        <translation>étape %1 attendue, aucune étape visible n&apos;est active (State = %2)</translation>
    </message>
    <message>
        <source>expected %1 to fire, no transition fired</source>
        <translation>%1 devait être franchie, aucune transition ne l&apos;a été</translation>
    </message>
    <message>
        <source>expected %1 to fire, %2 fired</source>
        <translation>%1 devait être franchie, %2 l&apos;a été</translation>
    </message>
    <message>
        <source>expected no transition to fire, %1 fired</source>
        <translation>aucune transition ne devait être franchie, %1 l&apos;a été</translation>
    </message>
    <message>
        <source>expected token %1 = %2, it is %3</source>
        <translation>mémoire %1 = %2 attendue, elle vaut %3</translation>
    </message>
    <message>
        <source>expected %1 = %2, it is %3</source>
        <extracomment>a variable, the value expected, the value it has</extracomment>
        <translation>%1 = %2 attendu, la valeur est %3</translation>
    </message>
    <message>
        <source>unknown variable &apos;%1&apos;</source>
        <translation>variable &apos;%1&apos; inconnue</translation>
    </message>
    <message>
        <source>expected Entry = %1, it is %2</source>
        <translation>Entry = %1 attendu, il vaut %2</translation>
    </message>
    <message>
        <source>expected %1.Complete = %2, it is %3</source>
        <translation>%1.Complete = %2 attendu, il vaut %3</translation>
    </message>
    <message>
        <source>%1.Complete = FALSE</source>
        <extracomment>a macro-step or enclosing step; the transition waits for its Complete</extracomment>
        <translation>%1.Complete = FALSE</translation>
    </message>
    <message>
        <source>%1 fires first</source>
        <extracomment>a transition of higher priority whose condition holds</extracomment>
        <translation>%1 est franchie en premier</translation>
    </message>
    <message>
        <source>scan %1: %2</source>
        <extracomment>a scan number, then what differed</extracomment>
        <translation>cycle %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>expected &apos;at SCAN:&apos; at the start of the line, found %1</source>
        <extracomment>%1: the word found in quotes, or &quot;the end of the line&quot;; &apos;at SCAN:&apos; is scenario syntax</extracomment>
        <translation>&apos;at SCAN:&apos; attendu en début de ligne, trouvé %1</translation>
    </message>
    <message>
        <source>expected a scan number after &apos;at&apos;, found %1</source>
        <translation>numéro de cycle attendu après &apos;at&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected &apos;:&apos; after the scan number, found %1</source>
        <translation>&apos;:&apos; attendu après le numéro de cycle, trouvé %1</translation>
    </message>
    <message>
        <source>expected &apos;set&apos; or &apos;expect&apos;, found %1</source>
        <translation>&apos;set&apos; ou &apos;expect&apos; attendu, trouvé %1</translation>
    </message>
    <message>
        <source>expected a variable name or &apos;complete STEP&apos;, found %1</source>
        <translation>nom de variable ou &apos;complete STEP&apos; attendu, trouvé %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;complete&apos;, found %1</source>
        <translation>identifiant d&apos;étape attendu après &apos;complete&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;step&apos;, found %1</source>
        <translation>identifiant d&apos;étape attendu après &apos;step&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected a transition id or &apos;none&apos; after &apos;fired&apos;, found %1</source>
        <translation>identifiant de transition ou &apos;none&apos; attendu après &apos;fired&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected a token name after &apos;token&apos;, found %1</source>
        <translation>nom de mémoire attendu après &apos;token&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected a variable name after &apos;variable&apos;, found %1</source>
        <translation>nom de variable attendu après &apos;variable&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the step id, found %1</source>
        <translation>&apos;=&apos; attendu après l&apos;identifiant d&apos;étape, trouvé %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the variable name, found %1</source>
        <translation>&apos;=&apos; attendu après le nom de variable, trouvé %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after the token name, found %1</source>
        <translation>&apos;=&apos; attendu après le nom de mémoire, trouvé %1</translation>
    </message>
    <message>
        <source>expected &apos;=&apos; after &apos;entry&apos;, found %1</source>
        <translation>&apos;=&apos; attendu après &apos;entry&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected a value after &apos;=&apos;, found %1</source>
        <translation>valeur attendue après &apos;=&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected TRUE or FALSE, found %1</source>
        <translation>TRUE ou FALSE attendu, trouvé %1</translation>
    </message>
    <message>
        <source>expected TRUE, FALSE or auto, found %1</source>
        <extracomment>auto is scenario syntax</extracomment>
        <translation>TRUE, FALSE ou auto attendu, trouvé %1</translation>
    </message>
    <message>
        <source>expected &apos;,&apos; or the end of the line, found %1</source>
        <translation>&apos;,&apos; ou fin de ligne attendu, trouvé %1</translation>
    </message>
    <message>
        <source>expected the end of the line, found %1</source>
        <translation>fin de ligne attendue, trouvé %1</translation>
    </message>
    <message>
        <source>scans are numbered from 1</source>
        <translation>les cycles sont numérotés à partir de 1</translation>
    </message>
    <message>
        <source>%1 is %2: %3</source>
        <extracomment>a variable, its IEC type (INT), then why the value does not fit it</extracomment>
        <translation>%1 est de type %2&#xa0;: %3</translation>
    </message>
    <message>
        <source>step %1 is hidden: it does not exist for the simulator</source>
        <translation>l&apos;étape %1 est masquée&#xa0;: elle n&apos;existe pas pour le simulateur</translation>
    </message>
    <message>
        <source>unknown step &apos;%1&apos;</source>
        <translation>étape &apos;%1&apos; inconnue</translation>
    </message>
    <message>
        <source>step %1 is a simple step: it has no Complete</source>
        <translation>l&apos;étape %1 est une étape simple&#xa0;: elle n&apos;a pas de Complete</translation>
    </message>
    <message>
        <source>transition %1 is not effective (it or one of its steps is hidden)</source>
        <translation>la transition %1 n&apos;est pas effective (elle ou l&apos;une de ses étapes est masquée)</translation>
    </message>
    <message>
        <source>unknown transition &apos;%1&apos;</source>
        <translation>transition &apos;%1&apos; inconnue</translation>
    </message>
    <message>
        <source>unknown token &apos;%1&apos;</source>
        <translation>mémoire &apos;%1&apos; inconnue</translation>
    </message>
    <message>
        <source>the end of the line</source>
        <translation>la fin de la ligne</translation>
    </message>
    <message>
        <source>invalid UTF-8: a scenario file must be UTF-8 text</source>
        <translation>UTF-8 non valide&#xa0;: un fichier de scénario doit être du texte UTF-8</translation>
    </message>
    <message>
        <source>%1&apos;s Complete is set to two values in scan %2: %3 on line %4, %5 on line %6</source>
        <extracomment>a step id, a scan number, then each value with the line that sets it</extracomment>
        <translation>le Complete de %1 reçoit deux valeurs au cycle %2&#xa0;: %3 ligne %4, %5 ligne %6</translation>
    </message>
    <message>
        <source>%1 is set to two values in scan %2: %3 on line %4, %5 on line %6</source>
        <extracomment>a variable, a scan number, then each value with the line that sets it</extracomment>
        <translation>%1 reçoit deux valeurs au cycle %2&#xa0;: %3 ligne %4, %5 ligne %6</translation>
    </message>
    <message>
        <source>expected the active steps of %1 to be %2, they are %3</source>
        <extracomment>%1: a GEMMA step; %2, %3: lists of nested step numbers</extracomment>
        <translation>étapes actives de %1 attendues : %2, elles sont : %3</translation>
    </message>
    <message>
        <source>expected %1.Unstable = %2, it is %3</source>
        <translation>%1.Unstable = %2 attendu, il vaut %3</translation>
    </message>
    <message>
        <source>expected step, fired, token, variable, entry, complete or nested after &apos;expect&apos;, found %1</source>
        <extracomment>step, fired, token, variable, entry and complete are scenario syntax</extracomment>
        <translation>step, fired, token, variable, entry, complete ou nested attendu après &apos;expect&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected a step id after &apos;nested&apos;, found %1</source>
        <translation>identifiant d&apos;étape attendu après « nested », trouvé %1</translation>
    </message>
    <message>
        <source>expected &apos;steps&apos; or &apos;unstable&apos; after the step id, found %1</source>
        <extracomment>steps and unstable are scenario syntax</extracomment>
        <translation>« steps » ou « unstable » attendu après l&apos;identifiant d&apos;étape, trouvé %1</translation>
    </message>
    <message>
        <source>expected a step number, found %1</source>
        <translation>numéro d&apos;étape attendu, trouvé %1</translation>
    </message>
    <message>
        <source>%1 is an output variable: the program writes it, a scenario sets only inputs</source>
        <translation>%1 est une variable de sortie : le programme l&apos;écrit, un scénario ne règle que les entrées</translation>
    </message>
    <message>
        <source>%1 is an internal variable: the program writes it, a scenario sets only inputs</source>
        <translation>%1 est une variable interne : le programme l&apos;écrit, un scénario ne règle que les entrées</translation>
    </message>
    <message>
        <source>step %1 has no nested GRAFCET</source>
        <translation>l&apos;étape %1 n&apos;a pas de GRAFCET imbriqué</translation>
    </message>
    <message>
        <source>the Complete of %1 comes from its nested GRAFCET: it cannot be set</source>
        <translation>le Complete de %1 vient de son GRAFCET imbriqué : il ne peut pas être réglé</translation>
    </message>
    <message>
        <source>step %1 is not active</source>
        <extracomment>an upstream step of a nested GRAFCET&apos;s transition</extracomment>
        <translation>l&apos;étape %1 n&apos;est pas active</translation>
    </message>
    <message>
        <source>steps %1 are not active</source>
        <extracomment>the upstream steps of a nested GRAFCET&apos;s transition (&quot;2, 3&quot;)</extracomment>
        <translation>les étapes %1 ne sont pas actives</translation>
    </message>
    <message>
        <source>no rising edge of %1 this scan (%1 = %2, at the end of the previous scan %3)</source>
        <extracomment>%1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan</extracomment>
        <translation>pas de front montant de %1 dans ce cycle (%1 = %2, à la fin du cycle précédent %3)</translation>
    </message>
    <message>
        <source>no falling edge of %1 this scan (%1 = %2, at the end of the previous scan %3)</source>
        <extracomment>%1: a BOOL variable; %2: its value now; %3: its value at the end of the previous scan</extracomment>
        <translation>pas de front descendant de %1 dans ce cycle (%1 = %2, à la fin du cycle précédent %3)</translation>
    </message>
    <message>
        <source>%1 is FALSE: step %2 active for %3 ms of %4 ms</source>
        <extracomment>%1: a time-dependent receptivity (&quot;5s/X2&quot;); %2: its step; %3 of %4: elapsed and set time in ms</extracomment>
        <translation>%1 est FALSE : étape %2 active depuis %3 ms sur %4 ms</translation>
    </message>
    <message>
        <source>%1 is not the active step: its GRAFCET does not evolve in the next scan</source>
        <extracomment>a macro-step or enclosing step</extracomment>
        <translation>%1 n&apos;est pas l&apos;étape active : son GRAFCET n&apos;évolue pas au prochain cycle</translation>
    </message>
    <message>
        <source>scan number %1 is too large: a scenario runs at most %2 scans</source>
        <extracomment>%2: the highest scan number a scenario may name</extracomment>
        <translation>le numéro de cycle %1 est trop grand : un scénario dure au plus %2 cycles</translation>
    </message>
    <message>
        <source>expected a command name after &apos;command&apos;, found %1</source>
        <extracomment>&apos;command&apos; is scenario syntax</extracomment>
        <translation>un nom de commande est attendu après &apos;command&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected a mode name or number after &apos;mode&apos;, found %1</source>
        <extracomment>&apos;mode&apos; is scenario syntax</extracomment>
        <translation>un nom ou un numéro de mode est attendu après &apos;mode&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected a state name after &apos;state&apos;, found %1</source>
        <extracomment>&apos;state&apos; is scenario syntax</extracomment>
        <translation>un nom d&apos;état est attendu après &apos;state&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos;</source>
        <translation>commande inconnue &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown unit mode &apos;%1&apos;</source>
        <translation>mode d&apos;unité inconnu &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown state &apos;%1&apos;</source>
        <translation>état inconnu &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown instance &apos;%1&apos;</source>
        <extracomment>%1: a PackML function block instance (Production_Resetting)</extracomment>
        <translation>instance inconnue &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is for PackML models only</source>
        <extracomment>%1: scenario syntax (&quot;command&quot;, &quot;expect state&quot;)</extracomment>
        <translation>&apos;%1&apos; ne s&apos;applique qu&apos;aux modèles PackML</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is for GEMMA models only</source>
        <extracomment>%1: scenario syntax (&quot;expect step&quot;, &quot;set complete&quot;)</extracomment>
        <translation>&apos;%1&apos; ne s&apos;applique qu&apos;aux modèles GEMMA</translation>
    </message>
    <message>
        <source>a %1 in scan %2 right after the one of line %3 is not seen: the request must be FALSE for one scan in between</source>
        <extracomment>%1: &quot;command&quot; or &quot;mode&quot; (scenario syntax); %2: a scan number; %3: a line number</extracomment>
        <translation>un %1 au cycle %2, juste après celui de la ligne %3, n&apos;est pas vu : la demande doit rester FALSE pendant un cycle entre les deux</translation>
    </message>
    <message>
        <source>%1 is a sensor of the machine&apos;s %2: the machine sets it; set it by hand in open loop only</source>
        <extracomment>%1: a variable; %2: the name of a component of the virtual machine (&quot;Clamp&quot;)</extracomment>
        <translation>%1 est un capteur du composant %2 de la machine : la machine le positionne ; ne le forcez à la main qu&apos;en boucle ouverte</translation>
    </message>
    <message>
        <source>expected a sensor or component name after &apos;fault&apos;, found %1</source>
        <extracomment>&apos;fault&apos; is scenario syntax</extracomment>
        <translation>nom de capteur ou de composant attendu après &apos;fault&apos;, trouvé %1</translation>
    </message>
    <message>
        <source>expected stuck, flicker, jam or clear after the name, found %1</source>
        <extracomment>stuck, flicker, jam and clear are scenario syntax</extracomment>
        <translation>stuck, flicker, jam ou clear attendu après le nom, trouvé %1</translation>
    </message>
    <message>
        <source>a fault needs the virtual machine: run the scenario in closed loop, on a model with a machine</source>
        <translation>une défaillance a besoin de la machine virtuelle : jouez le scénario en boucle fermée, sur un modèle qui a une machine</translation>
    </message>
    <message>
        <source>%1 is an operator input of the machine&apos;s %2: the user drives it with set; a fault applies to the machine&apos;s sensors</source>
        <extracomment>%1: a variable; %2: the name of a component of the virtual machine (&quot;Start&quot;); &apos;set&apos; is scenario syntax</extracomment>
        <translation>%1 est une entrée opérateur de %2 de la machine : l&apos;utilisateur la pilote avec set ; une défaillance s&apos;applique aux capteurs de la machine</translation>
    </message>
    <message>
        <source>%1 is no sensor of the machine: a fault applies to the inputs a component writes</source>
        <translation>%1 n&apos;est pas un capteur de la machine : une défaillance s&apos;applique aux entrées qu&apos;un composant écrit</translation>
    </message>
    <message>
        <source>no component &apos;%1&apos; in the machine</source>
        <translation>aucun composant &apos;%1&apos; dans la machine</translation>
    </message>
    <message>
        <source>%1 is a %2: only cylinders and conveyors jam</source>
        <extracomment>%1: a component of the virtual machine; %2: its kind as the file spells it (&quot;lamp&quot;, &quot;push-button&quot;)</extracomment>
        <translation>%1 est de type %2 : seuls les vérins et les convoyeurs se bloquent</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is neither a sensor nor a component of the machine</source>
        <translation>&apos;%1&apos; n&apos;est ni un capteur ni un composant de la machine</translation>
    </message>
</context>
<context>
    <name>SpecificationExport</name>
    <message>
        <source>%1 specification</source>
        <extracomment>the specification&apos;s title and the file name it is saved under; %1 is the model&apos;s name</extracomment>
        <translation>Spécification %1</translation>
    </message>
    <message>
        <source>GEMMA chart</source>
        <translation>Diagramme GEMMA</translation>
    </message>
    <message>
        <source>States</source>
        <translation>États</translation>
    </message>
    <message>
        <source>Transitions</source>
        <translation>Transitions</translation>
    </message>
    <message>
        <source>Variables</source>
        <translation>Variables</translation>
    </message>
    <message>
        <source>Nested GRAFCETs</source>
        <translation>GRAFCET imbriqués</translation>
    </message>
    <message>
        <source>Generated code</source>
        <translation>Code généré</translation>
    </message>
    <message>
        <source>Specification</source>
        <translation>Spécification</translation>
    </message>
    <message>
        <source>GEMMA-GRAFCET specification</source>
        <translation>Spécification GEMMA-GRAFCET</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n erreur</numerusform>
            <numerusform>%n erreurs</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n avertissement</numerusform>
            <numerusform>%n avertissements</numerusform>
        </translation>
    </message>
    <message>
        <source>File</source>
        <translation>Fichier</translation>
    </message>
    <message>
        <source>not saved yet</source>
        <translation>pas encore enregistré</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>Date</translation>
    </message>
    <message>
        <source>Initial state</source>
        <translation>État initial</translation>
    </message>
    <message>
        <source>PLC task cycle</source>
        <translation>Cycle de la tâche automate</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1&#xa0;ms</translation>
    </message>
    <message>
        <source>Code dialect</source>
        <translation>Dialecte du code</translation>
    </message>
    <message>
        <source>Nested GRAFCET evolution</source>
        <translation>Évolution des GRAFCET imbriqués</translation>
    </message>
    <message>
        <source>Until stable, in one call of its function block</source>
        <translation>Jusqu&apos;à stabilité, en un appel de son bloc fonctionnel</translation>
    </message>
    <message>
        <source>One evolution per PLC scan</source>
        <translation>Une évolution par cycle automate</translation>
    </message>
    <message>
        <source>Checks</source>
        <translation>Vérifications</translation>
    </message>
    <message>
        <source>No problems found</source>
        <translation>Aucun problème trouvé</translation>
    </message>
    <message>
        <source>Written by</source>
        <translation>Écrit par</translation>
    </message>
    <message>
        <source>GG Studio %1</source>
        <translation>GG Studio %1</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>Sommaire</translation>
    </message>
    <message>
        <source>GEMMA chart, continued</source>
        <translation>Diagramme GEMMA, suite</translation>
    </message>
    <message>
        <source>States, transitions and variables</source>
        <translation>États, transitions et variables</translation>
    </message>
    <message>
        <source>State</source>
        <translation>État</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>GRAFCET</source>
        <translation>GRAFCET</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Commentaire</translation>
    </message>
    <message>
        <source>%1, initial</source>
        <translation>%1, initiale</translation>
    </message>
    <message numerus="yes">
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n étape</numerusform>
            <numerusform>%n étapes</numerusform>
        </translation>
    </message>
    <message>
        <source>The visible states of the GEMMA chart, in state order. A macro-step or an enclosing step runs its nested GRAFCET while it is active.</source>
        <translation>Les états visibles du diagramme GEMMA, dans l&apos;ordre des états. Une macro-étape ou une étape encapsulante exécute son GRAFCET imbriqué tant qu&apos;elle est active.</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transition</translation>
    </message>
    <message>
        <source>Priority</source>
        <translation>Priorité</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Réceptivité</translation>
    </message>
    <message>
        <source>Tokens</source>
        <translation>Mémoires</translation>
    </message>
    <message>
        <source>%1, negated</source>
        <translation>%1, niée</translation>
    </message>
    <message>
        <source>The transitions that take part: visible, between visible states. A state evaluates its transitions by priority, 1 first; a negated transition fires when its condition is FALSE.</source>
        <translation>Les transitions qui comptent&#xa0;: visibles, entre des états visibles. Un état évalue ses transitions par priorité, 1 d&apos;abord&#xa0;; une transition niée est franchie quand sa réceptivité est FALSE.</translation>
    </message>
    <message>
        <source>No transition takes part.</source>
        <translation>Aucune transition ne compte.</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Nature</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Valeur initiale</translation>
    </message>
    <message>
        <source>The declared variables, in declaration order. Inputs are read from the machine, outputs written by the actions of the nested GRAFCETs, internal variables are the program&apos;s memory. A variable without a default starts at its type&apos;s (FALSE, 0).</source>
        <translation>Les variables déclarées, dans l&apos;ordre de leur déclaration. Les entrées sont lues sur la machine, les sorties écrites par les actions des GRAFCET imbriqués, les variables internes sont la mémoire du programme. Une variable sans valeur initiale démarre à celle de son type (FALSE, 0).</translation>
    </message>
    <message>
        <source>No variables are declared.</source>
        <translation>Aucune variable n&apos;est déclarée.</translation>
    </message>
    <message numerus="yes">
        <source>%n transition(s)</source>
        <translation>
            <numerusform>%n transition</numerusform>
            <numerusform>%n transitions</numerusform>
        </translation>
    </message>
    <message>
        <source>function block %1</source>
        <translation>bloc fonctionnel %1</translation>
    </message>
    <message>
        <source>This GRAFCET has no steps yet.</source>
        <translation>Ce GRAFCET n&apos;a pas encore d&apos;étapes.</translation>
    </message>
    <message>
        <source>Nested GRAFCET of %1, continued</source>
        <translation>GRAFCET imbriqué de %1, suite</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Étape</translation>
    </message>
    <message>
        <source>Steps of %1</source>
        <translation>Étapes de %1</translation>
    </message>
    <message>
        <source>GG Studio generates the PLC program as IEC 61131-3 Structured Text by the Hierarchical Design Pattern: the program %1 holds the active GEMMA state and evaluates its transitions by priority, and each visible macro-step or enclosing step is a function block that %1 calls while that state is active. This outline gives the program organisation units and their interfaces; File &gt; Export Structured Text and Export PLCopen XML write the code itself.</source>
        <translation>GG Studio génère le programme automate en Structured Text IEC 61131-3 selon le Hierarchical Design Pattern&#xa0;: le programme %1 tient l&apos;état GEMMA actif et évalue ses transitions par priorité, et chaque macro-étape ou étape encapsulante visible est un bloc fonctionnel que %1 appelle tant que cet état est actif. Ce plan donne les unités d&apos;organisation de programme et leurs interfaces&#xa0;; Fichier &gt; Exporter en texte structuré (ST) et Exporter en PLCopen XML écrivent le code lui-même.</translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s): the generated code marks each one with a comment.</source>
        <translation>
            <numerusform>Le modèle a %n erreur&#xa0;: le code généré la signale par un commentaire.</numerusform>
            <numerusform>Le modèle a %n erreurs&#xa0;: le code généré signale chacune par un commentaire.</numerusform>
        </translation>
    </message>
    <message>
        <source>Configuration</source>
        <translation>Configuration</translation>
    </message>
    <message>
        <source>Resource</source>
        <translation>Ressource</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Tâche</translation>
    </message>
    <message>
        <source>%1: cyclic, every %2, priority %3</source>
        <translation>%1&#xa0;: cyclique, toutes les %2, priorité %3</translation>
    </message>
    <message>
        <source>Program instance</source>
        <translation>Instance du programme</translation>
    </message>
    <message>
        <source>Global variable list</source>
        <translation>Liste de variables globales</translation>
    </message>
    <message>
        <source>The GEMMA layer: it holds the active state in State, evaluates that state&apos;s transitions by priority and calls the function block of a state with nested behaviour while that state is active.</source>
        <translation>La couche GEMMA&#xa0;: elle tient l&apos;état actif dans State, évalue les transitions de cet état par priorité et appelle le bloc fonctionnel d&apos;un état au comportement imbriqué tant que cet état est actif.</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1 (page %2). %3 calls it through its instance %4 while %4 is active.</source>
        <translation>Le GRAFCET imbriqué de %1 (page %2). %3 l&apos;appelle par son instance %4 tant que %4 est active.</translation>
    </message>
    <message>
        <source>The nested behaviour of %1, not written yet: until it is, the function block completes at once. %2 calls it through its instance %3.</source>
        <translation>Le comportement imbriqué de %1, pas encore écrit&#xa0;: en attendant, le bloc fonctionnel se termine aussitôt. %2 l&apos;appelle par son instance %3.</translation>
    </message>
    <message>
        <source>Declaration</source>
        <translation>Déclaration</translation>
    </message>
    <message>
        <source>Initial value</source>
        <translation>Valeur initiale</translation>
    </message>
    <message>
        <source>Global variables it reads (VAR_EXTERNAL): %1.</source>
        <translation>Variables globales qu&apos;il lit (VAR_EXTERNAL)&#xa0;: %1.</translation>
    </message>
    <message>
        <source>Its own variables (VAR): %1.</source>
        <translation>Ses propres variables (VAR)&#xa0;: %1.</translation>
    </message>
    <message>
        <source>Global variables</source>
        <translation>Variables globales</translation>
    </message>
    <message>
        <source>in the VAR_GLOBAL of the configuration %1</source>
        <translation>dans le VAR_GLOBAL de la configuration %1</translation>
    </message>
    <message>
        <source>in the global variable list %1</source>
        <translation>dans la liste de variables globales %1</translation>
    </message>
    <message>
        <source>The declared variables (page %1) are the program&apos;s global variables, %2.</source>
        <translation>Les variables déclarées (page %1) sont les variables globales du programme, %2.</translation>
    </message>
    <message>
        <source>The generator adds these:</source>
        <translation>Le générateur ajoute celles-ci&#xa0;:</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Page %1 sur %2</translation>
    </message>
    <message>
        <source>PackML chart</source>
        <translation>Diagramme PackML</translation>
    </message>
    <message>
        <source>Commands, modes and variables</source>
        <translation>Commandes, modes et variables</translation>
    </message>
    <message>
        <source>Unit mode %1</source>
        <translation>Mode d&apos;unité %1</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Commandes</translation>
    </message>
    <message>
        <source>Unit modes</source>
        <translation>Modes d&apos;unité</translation>
    </message>
    <message>
        <source>PackML, 2022 edition</source>
        <translation>PackML, édition 2022</translation>
    </message>
    <message>
        <source>PackML, 2015 edition</source>
        <translation>PackML, édition 2015</translation>
    </message>
    <message>
        <source>Hold accepted in Suspended</source>
        <translation>Hold accepté dans Suspended</translation>
    </message>
    <message>
        <source>Complete accepted in Suspended and Held</source>
        <translation>Complete accepté dans Suspended et Held</translation>
    </message>
    <message>
        <source>%1; options: %2</source>
        <translation>%1 ; options : %2</translation>
    </message>
    <message>
        <source>Template</source>
        <translation>Modèle</translation>
    </message>
    <message>
        <source>Initial unit mode</source>
        <translation>Mode d&apos;unité initial</translation>
    </message>
    <message>
        <source>PackML specification</source>
        <translation>Spécification PackML</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Commande</translation>
    </message>
    <message>
        <source>CntrlCmd</source>
        <translation>CntrlCmd</translation>
    </message>
    <message>
        <source>The commands of the edition, with the condition whose rising edge issues each one (besides CntrlCmd). A command a state does not accept is ignored there.</source>
        <translation>Les commandes de l&apos;édition, avec la condition dont le front montant émet chacune (en plus de CntrlCmd). Une commande qu&apos;un état n&apos;accepte pas y est ignorée.</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <source>Request condition</source>
        <translation>Condition de demande</translation>
    </message>
    <message>
        <source>Disabled states</source>
        <translation>États désactivés</translation>
    </message>
    <message>
        <source>Mode change allowed in</source>
        <translation>Changement de mode permis dans</translation>
    </message>
    <message>
        <source>The unit modes, in number order. A mode skips its disabled states; the unit changes to a mode when its request condition rises while the current mode allows a change in the current state.</source>
        <translation>Les modes d&apos;unité, par numéro. Un mode saute ses états désactivés ; l&apos;unité passe à un mode quand sa condition de demande monte alors que le mode courant permet un changement dans l&apos;état courant.</translation>
    </message>
    <message>
        <source>Nested GRAFCET</source>
        <translation>GRAFCET imbriqué</translation>
    </message>
    <message>
        <source>Nested GRAFCETs in %1</source>
        <translation>GRAFCET imbriqués en %1</translation>
    </message>
    <message>
        <source>None: the mode disables this state</source>
        <translation>Aucun : le mode désactive cet état</translation>
    </message>
    <message>
        <source>Own: %1</source>
        <translation>Propre : %1</translation>
    </message>
    <message>
        <source>Same as mode %1: %2</source>
        <translation>Le même que le mode %1 : %2</translation>
    </message>
    <message>
        <source>Same as mode %1, which does not exist</source>
        <translation>Le même que le mode %1, qui n&apos;existe pas</translation>
    </message>
    <message>
        <source>None: the state completes at once</source>
        <translation>Aucun : l&apos;état se termine aussitôt</translation>
    </message>
    <message>
        <source>None: Execute waits for a command</source>
        <translation>Aucun : Execute attend une commande</translation>
    </message>
    <message>
        <source>Nested GRAFCET %1, continued</source>
        <translation>GRAFCET imbriqué %1, suite</translation>
    </message>
    <message>
        <source>GG Studio generates the PLC program as IEC 61131-3 Structured Text by the PackML design pattern: the program %1 is the state and mode manager, with the PackTags interface; it calls, in each acting state and Execute, the function block instance of the current unit mode and state, whose State Complete ends that state. This outline gives the program organisation units and their interfaces; File &gt; Export Structured Text and Export PLCopen XML write the code itself.</source>
        <translation>GG Studio génère le programme de l&apos;automate en texte structuré CEI 61131-3 selon le patron de conception PackML : le programme %1 est le gestionnaire d&apos;états et de modes, avec l&apos;interface PackTags ; il appelle, dans chaque état actif et dans Execute, l&apos;instance de bloc fonctionnel du mode d&apos;unité et de l&apos;état courants, dont le State Complete termine cet état. Ce plan donne les unités d&apos;organisation de programme et leurs interfaces ; Fichier &gt; Exporter le texte structuré et Exporter en PLCopen XML écrivent le code lui-même.</translation>
    </message>
    <message>
        <source>The PackML state and mode manager: it latches the commands and mode requests, holds the current state and unit mode in StateCurrent and UnitModeCurrent, evaluates the current state&apos;s transitions in the current mode and calls the function block instance of that mode and state.</source>
        <translation>Le gestionnaire d&apos;états et de modes PackML : il mémorise les commandes et les demandes de mode, tient l&apos;état et le mode d&apos;unité courants dans StateCurrent et UnitModeCurrent, évalue les transitions de l&apos;état courant dans le mode courant et appelle l&apos;instance de bloc fonctionnel de ce mode et de cet état.</translation>
    </message>
    <message>
        <source>The nested GRAFCET %1 (page %2). %3 calls it while the unit is in %4 in a mode that runs it; its Complete is that state&apos;s State Complete.</source>
        <translation>Le GRAFCET imbriqué %1 (page %2). %3 l&apos;appelle tant que l&apos;unité est dans %4 dans un mode qui l&apos;exécute ; son Complete est le State Complete de cet état.</translation>
    </message>
    <message>
        <source>The function block of %1 in the modes without a GRAFCET there: %2</source>
        <translation>Le bloc fonctionnel de %1 dans les modes sans GRAFCET à cet endroit : %2</translation>
    </message>
    <message>
        <source>it completes at once.</source>
        <translation>il se termine aussitôt.</translation>
    </message>
    <message>
        <source>it does nothing, Execute waits for a command.</source>
        <translation>il ne fait rien, Execute attend une commande.</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Component</source>
        <translation>Composant</translation>
    </message>
    <message>
        <source>Wiring</source>
        <translation>Câblage</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Réglages</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>illimité</translation>
    </message>
    <message>
        <source>Feeds %1</source>
        <translation>Alimente %1</translation>
    </message>
    <message>
        <source>The virtual machine the simulation runs the program against, in closed loop: after each scan the components move one cycle time from the outputs wired to them and set the sensors the next scan reads; operator inputs stay the user&apos;s. Times are in milliseconds, counted in whole cycles.</source>
        <translation>La machine virtuelle contre laquelle la simulation exécute le programme, en boucle fermée : après chaque cycle, les composants se déplacent d&apos;un temps de cycle selon les sorties qui leur sont câblées et fixent les capteurs que lit le cycle suivant ; les entrées opérateur restent à l&apos;utilisateur. Les temps sont en millisecondes, comptés en cycles entiers.</translation>
    </message>
    <message>
        <source>The machine at rest</source>
        <translation>La machine au repos</translation>
    </message>
</context>
<context>
    <name>StateNames</name>
    <message>
        <source>Stop in initial state</source>
        <translation>Arrêt dans l&apos;état initial</translation>
    </message>
    <message>
        <source>Stop requested at end of cycle</source>
        <translation>Arrêt demandé en fin de cycle</translation>
    </message>
    <message>
        <source>Stop requested in a given state</source>
        <translation>Arrêt demandé dans un état déterminé</translation>
    </message>
    <message>
        <source>Stop obtained</source>
        <translation>Arrêt obtenu</translation>
    </message>
    <message>
        <source>Preparation for restart after failure</source>
        <translation>Préparation pour remise en route après défaillance</translation>
    </message>
    <message>
        <source>Operative part reset to initial state</source>
        <translation>Mise P.O. dans l&apos;état initial</translation>
    </message>
    <message>
        <source>Operative part set to a given state</source>
        <translation>Mise P.O. dans un état déterminé</translation>
    </message>
    <message>
        <source>Normal production</source>
        <translation>Production normale</translation>
    </message>
    <message>
        <source>Preparation run</source>
        <translation>Marche de préparation</translation>
    </message>
    <message>
        <source>Closing run</source>
        <translation>Marche de clôture</translation>
    </message>
    <message>
        <source>Verification run out of order</source>
        <translation>Marche de vérification dans le désordre</translation>
    </message>
    <message>
        <source>Verification run in order</source>
        <translation>Marche de vérification dans l&apos;ordre</translation>
    </message>
    <message>
        <source>Test run</source>
        <translation>Marche de test</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Arrêt d&apos;urgence</translation>
    </message>
    <message>
        <source>Diagnosis and/or failure handling</source>
        <translation>Diagnostic et/ou traitement de défaillance</translation>
    </message>
    <message>
        <source>Production despite failure</source>
        <translation>Production tout de même</translation>
    </message>
    <message>
        <source>Stop procedures</source>
        <translation>Procédures d&apos;arrêt</translation>
    </message>
    <message>
        <source>Operation procedures</source>
        <translation>Procédures de fonctionnement</translation>
    </message>
    <message>
        <source>Failure procedures</source>
        <translation>Procédures en défaillance</translation>
    </message>
</context>
<context>
    <name>ValueProblemText</name>
    <message>
        <source>&apos;%1&apos; is not an %2 literal: write a whole number such as 42</source>
        <extracomment>%1: the value as written; %2: INT</extracomment>
        <translation>&apos;%1&apos; n&apos;est pas un littéral %2&#xa0;: écrivez un nombre entier, par exemple 42</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a %2 literal: write a whole number such as 42</source>
        <extracomment>%1: the value as written; %2: an integer type other than INT (SINT, UDINT...)</extracomment>
        <translation>&apos;%1&apos; n&apos;est pas un littéral %2&#xa0;: écrivez un nombre entier, par exemple 42</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has leading or trailing spaces</source>
        <translation>&apos;%1&apos; a des espaces au début ou à la fin</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a BOOL literal (TRUE or FALSE)</source>
        <translation>&apos;%1&apos; n&apos;est pas un littéral BOOL (TRUE ou FALSE)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a %2 literal: write a decimal number such as 1.5 or 2.0E3</source>
        <extracomment>%1: the value as written; %2: REAL or LREAL</extracomment>
        <translation>&apos;%1&apos; n&apos;est pas un littéral %2&#xa0;: écrivez un nombre décimal, par exemple 1.5 ou 2.0E3</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is out of range for %2 (%3..%4)</source>
        <extracomment>%1: the value as written; %2: its IEC type; %3..%4: the type&apos;s range</extracomment>
        <translation>&apos;%1&apos; est hors limites pour %2 (%3..%4)</translation>
    </message>
</context>
<context>
    <name>editor::Autosave</name>
    <message>
        <source>Cannot create the folder %1 for recovery copies</source>
        <translation>Impossible de créer le dossier %1 des copies de récupération</translation>
    </message>
    <message>
        <source>Cannot write the recovery copy: %1</source>
        <translation>Impossible d&apos;écrire la copie de récupération&#xa0;: %1</translation>
    </message>
    <message>
        <source>Cannot lock the recovery copy %1</source>
        <translation>Impossible de verrouiller la copie de récupération %1</translation>
    </message>
    <message>
        <source>Another GG Studio is using the recovery copy %1.</source>
        <translation>Une autre instance de GG Studio utilise la copie de récupération %1.</translation>
    </message>
</context>
<context>
    <name>editor::BranchDrag</name>
    <message>
        <source>Step %1 is on no branch of a divergence: there is no branch to move</source>
        <translation>L’étape %1 n’est sur aucune branche d’une divergence : il n’y a pas de branche à déplacer</translation>
    </message>
    <message>
        <source>Move the branch of step %1 left in %2</source>
        <translation>Déplacer la branche de l’étape %1 vers la gauche dans %2</translation>
    </message>
    <message>
        <source>Move the branch of step %1 right in %2</source>
        <translation>Déplacer la branche de l’étape %1 vers la droite dans %2</translation>
    </message>
</context>
<context>
    <name>editor::ChartContextMenu</name>
    <message>
        <source>&amp;Show %1</source>
        <translation>&amp;Afficher %1</translation>
    </message>
    <message>
        <source>&amp;Hide %1</source>
        <translation>&amp;Masquer %1</translation>
    </message>
    <message>
        <source>Step &amp;Type</source>
        <translation>&amp;Type d&apos;étape</translation>
    </message>
    <message>
        <source>Make &amp;Initial Step</source>
        <translation>Faire l&apos;étape &amp;initiale</translation>
    </message>
    <message>
        <source>Edit &amp;Comment…</source>
        <translation>Modifier le &amp;commentaire…</translation>
    </message>
    <message>
        <source>Edit &amp;Condition…</source>
        <translation>Modifier la &amp;réceptivité…</translation>
    </message>
    <message>
        <source>&amp;Negated</source>
        <translation>&amp;Niée</translation>
    </message>
    <message>
        <source>Flips whether this transition waits for Complete of its source&apos;s nested behaviour</source>
        <translation>Inverse l&apos;attente par cette transition de Complete du comportement imbriqué de son étape source</translation>
    </message>
    <message>
        <source>Priority &amp;Up</source>
        <translation>&amp;Monter la priorité</translation>
    </message>
    <message>
        <source>Priority &amp;Down</source>
        <translation>&amp;Baisser la priorité</translation>
    </message>
    <message numerus="yes">
        <source>Hide the %n Selected Elements</source>
        <translation>
            <numerusform>Masquer l&apos;élément sélectionné</numerusform>
            <numerusform>Masquer les %n éléments sélectionnés</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Show the %n Selected Elements</source>
        <translation>
            <numerusform>Afficher l&apos;élément sélectionné</numerusform>
            <numerusform>Afficher les %n éléments sélectionnés</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Open Nested GRAFCET</source>
        <translation>&amp;Ouvrir le GRAFCET imbriqué</translation>
    </message>
</context>
<context>
    <name>editor::ConditionList</name>
    <message>
        <source>[%1] %2: %3</source>
        <extracomment>an entry of the Conditions list under an exported chart: note number, transition, its condition in full</extracomment>
        <translation>[%1] %2&#xa0;: %3</translation>
    </message>
    <message>
        <source>Conditions</source>
        <translation>Réceptivités</translation>
    </message>
</context>
<context>
    <name>editor::ConnectTransitionDialog</name>
    <message>
        <source>Connect T%1 of %2</source>
        <extracomment>%1 the transition&apos;s number, %2 the GEMMA step whose GRAFCET it is in</extracomment>
        <translation>Relier T%1 de %2</translation>
    </message>
    <message>
        <source>Upstream steps (it leaves them)</source>
        <translation>Étapes amont (elle les désactive)</translation>
    </message>
    <message>
        <source>Downstream steps (it activates them)</source>
        <translation>Étapes aval (elle les active)</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Étape %1</translation>
    </message>
    <message>
        <source>Tick an upstream step: a transition leaves at least one step.</source>
        <translation>Cochez une étape amont : une transition quitte au moins une étape.</translation>
    </message>
    <message>
        <source>Tick a downstream step: a transition activates at least one step. To end a branch on a step with no transition after it, use Add Branch Ending on a Step on the step.</source>
        <translation>Cochez une étape aval : une transition active au moins une étape. Pour finir une branche sur une étape sans transition après elle, utilisez « Ajouter une branche finissant sur une étape » sur l’étape.</translation>
    </message>
</context>
<context>
    <name>editor::Document</name>
    <message>
        <source>%1: %2</source>
        <translation>%1&#xa0;: %2</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <source>Stop the simulation to edit the model</source>
        <translation>Arrêtez la simulation pour modifier le modèle</translation>
    </message>
</context>
<context>
    <name>editor::ExportActions</name>
    <message>
        <source>Export &amp;PLCopen XML…</source>
        <translation>Exporter en &amp;PLCopen XML…</translation>
    </message>
    <message>
        <source>Write the PLC program as PLCopen XML, to import into a PLC programming tool</source>
        <translation>Écrire le programme automate en PLCopen XML, à importer dans un outil de programmation d&apos;automates</translation>
    </message>
    <message>
        <source>Export &amp;Structured Text…</source>
        <translation>Exporter en &amp;texte structuré (ST)…</translation>
    </message>
    <message>
        <source>Write the PLC program as IEC 61131-3 Structured Text files</source>
        <translation>Écrire le programme automate en fichiers de texte structuré (ST) IEC 61131-3</translation>
    </message>
    <message>
        <source>Export &amp;GG-Generator JSON…</source>
        <translation>Exporter en JSON &amp;GG-Generator…</translation>
    </message>
    <message>
        <source>Save the model in the format of the GG-Generator web tool</source>
        <translation>Enregistrer le modèle au format de l&apos;outil web GG-Generator</translation>
    </message>
    <message>
        <source>Export &amp;Chart…</source>
        <translation>Exporter le &amp;diagramme…</translation>
    </message>
    <message>
        <source>Save the chart as an SVG, PNG or PDF picture</source>
        <translation>Enregistrer le diagramme comme image SVG, PNG ou PDF</translation>
    </message>
    <message>
        <source>&amp;Print…</source>
        <translation>&amp;Imprimer…</translation>
    </message>
    <message>
        <source>Print the chart</source>
        <translation>Imprimer le diagramme</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… et %n autre</numerusform>
            <numerusform>… et %n autres</numerusform>
        </translation>
    </message>
    <message>
        <source>Export a Model with Errors</source>
        <translation>Exporter un modèle contenant des erreurs</translation>
    </message>
    <message numerus="yes">
        <source>The model has %n error(s). The generated code marks each one with a comment, but it may not compile or may not behave as intended.</source>
        <translation>
            <numerusform>Le modèle contient %n erreur. Le code généré la signale par un commentaire, mais il risque de ne pas compiler ou de ne pas se comporter comme prévu.</numerusform>
            <numerusform>Le modèle contient %n erreurs. Le code généré signale chacune d&apos;elles par un commentaire, mais il risque de ne pas compiler ou de ne pas se comporter comme prévu.</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Export Anyway</source>
        <translation>&amp;Exporter quand même</translation>
    </message>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Exporter en PLCopen XML</translation>
    </message>
    <message>
        <source>PLCopen XML (*.xml)</source>
        <translation>PLCopen XML (*.xml)</translation>
    </message>
    <message>
        <source>Export Structured Text</source>
        <translation>Exporter en texte structuré (ST)</translation>
    </message>
    <message>
        <source>Structured Text (*.st)</source>
        <translation>Texte structuré (*.st)</translation>
    </message>
    <message>
        <source>Export Structured Text to a Folder</source>
        <translation>Exporter en texte structuré (ST) dans un dossier</translation>
    </message>
    <message>
        <source>Export GG-Generator JSON</source>
        <translation>Exporter en JSON GG-Generator</translation>
    </message>
    <message>
        <source>GG-Generator JSON (*.json)</source>
        <translation>JSON GG-Generator (*.json)</translation>
    </message>
    <message>
        <source>SVG picture (*.svg)</source>
        <translation>Image SVG (*.svg)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Image PNG (*.png)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>Document PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export Chart</source>
        <translation>Exporter le diagramme</translation>
    </message>
    <message>
        <source>Print Chart</source>
        <translation>Imprimer le diagramme</translation>
    </message>
    <message>
        <source>The printer could not be started.</source>
        <translation>L&apos;imprimante n&apos;a pas pu être démarrée.</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>Exporté vers %1</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Échec de l&apos;export</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>Impossible d&apos;écrire %1.</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>sans titre</translation>
    </message>
    <message>
        <source>The nested GRAFCETs of %1: GG-Generator has no place for nested behaviour.</source>
        <translation>Les GRAFCET imbriqués de %1&#xa0;: GG-Generator n&apos;a pas de place pour le comportement imbriqué.</translation>
    </message>
    <message>
        <source>The variable kinds (output, internal): GG-Generator reads every variable as an input.</source>
        <translation>Les genres des variables (sortie, interne)&#xa0;: GG-Generator lit chaque variable comme une entrée.</translation>
    </message>
    <message>
        <source>The until-stable evolution rule: GG-Generator knows one evolution per scan only.</source>
        <translation>La règle d&apos;évolution «&#xa0;jusqu&apos;à stabilité&#xa0;»&#xa0;: GG-Generator ne connaît qu&apos;une évolution par cycle.</translation>
    </message>
    <message>
        <source>Export to GG-Generator</source>
        <translation>Exporter vers GG-Generator</translation>
    </message>
    <message>
        <source>The GG-Generator file will leave out part of this model. Your model and its own file keep everything.</source>
        <translation>Le fichier GG-Generator laissera de côté une partie de ce modèle. Votre modèle et son propre fichier conservent tout.</translation>
    </message>
    <message>
        <source>%1, nested GRAFCET of %2</source>
        <translation>%1, GRAFCET imbriqué de %2</translation>
    </message>
    <message>
        <source>Export Speci&amp;fication…</source>
        <translation>Exporter la spé&amp;cification…</translation>
    </message>
    <message>
        <source>Write the whole model as one PDF document: the chart, the states, the variables, every nested GRAFCET and the outline of the generated code</source>
        <translation>Écrire tout le modèle dans un seul document PDF&#xa0;: le diagramme, les états, les variables, chaque GRAFCET imbriqué et le plan du code généré</translation>
    </message>
    <message>
        <source>Export Specification</source>
        <translation>Exporter la spécification</translation>
    </message>
    <message>
        <source>The verification properties: GG-Generator has no place for them.</source>
        <translation>Les propriétés à vérifier&#xa0;: GG-Generator n&apos;a pas de place pour elles.</translation>
    </message>
    <message>
        <source>Writing the specification…</source>
        <translation>Écriture de la spécification…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Export cancelled: %1 left unchanged</source>
        <translation>Export annulé : %1 n&apos;a pas été modifié</translation>
    </message>
</context>
<context>
    <name>editor::ExportOptionsDialog</name>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Exporter en PLCopen XML</translation>
    </message>
    <message>
        <source>Export Structured Text</source>
        <translation>Exporter en texte structuré (ST)</translation>
    </message>
    <message>
        <source>One file per POU, in a &amp;folder</source>
        <translation>Un fichier par POU, dans un d&amp;ossier</translation>
    </message>
    <message>
        <source>One &amp;IEC 61131-3 file with every POU</source>
        <translation>Un seul fichier &amp;IEC 61131-3 avec toutes les POU</translation>
    </message>
    <message>
        <source>Files:</source>
        <translation>Fichiers&#xa0;:</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialecte&#xa0;:</translation>
    </message>
    <message>
        <source>IEC writes PLCopen TC6 XML 2.01 with the globals in the configuration. CODESYS writes what CODESYS V3.5 imports, with a GVL.</source>
        <translation>IEC écrit du PLCopen TC6 XML 2.01 avec les variables globales dans la configuration. CODESYS écrit ce que CODESYS V3.5 importe, avec une GVL.</translation>
    </message>
    <message>
        <source>The single file is always IEC 61131-3: CODESYS code names a GVL that IEC compilers do not know.</source>
        <translation>Le fichier unique est toujours en IEC 61131-3&#xa0;: le code CODESYS fait référence à une GVL que les compilateurs IEC ne connaissent pas.</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exporter…</translation>
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
        <translation>Insérer une étape &amp;après</translation>
    </message>
    <message>
        <source>Insert Step &amp;Before</source>
        <translation>Insérer une étape &amp;avant</translation>
    </message>
    <message>
        <source>Add &amp;Selection Branch</source>
        <translation>Ajouter une branche de &amp;sélection</translation>
    </message>
    <message>
        <source>Add &amp;Parallel Branch</source>
        <translation>Ajouter une branche &amp;parallèle</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <source>Remove Bra&amp;nch</source>
        <translation>Supprimer la bra&amp;nche</translation>
    </message>
    <message>
        <source>Ren&amp;umber Steps and Transitions</source>
        <translation>Ren&amp;uméroter étapes et transitions</translation>
    </message>
    <message>
        <source>&amp;Connect Directly…</source>
        <translation>&amp;Relier directement…</translation>
    </message>
    <message>
        <source>&amp;Copy Steps</source>
        <translation>&amp;Copier les étapes</translation>
    </message>
    <message>
        <source>&amp;Paste Steps</source>
        <translation>C&amp;oller les étapes</translation>
    </message>
    <message>
        <source>Create the &amp;Usual Shape</source>
        <translation>Créer la forme &amp;usuelle</translation>
    </message>
    <message>
        <source>Initial step 1, then step 2, then step 3, which sets Complete</source>
        <translation>Étape initiale 1, puis étape 2, puis étape 3, qui met Complete à TRUE</translation>
    </message>
    <message>
        <source>%1 has no GRAFCET yet.&lt;br&gt;&lt;a href=&quot;create&quot;&gt;Create the usual shape&lt;/a&gt;: initial step 1, step 2, and step 3, which sets Complete.</source>
        <extracomment>%1 the GEMMA step; the link creates its GRAFCET</extracomment>
        <translation>%1 n’a pas encore de GRAFCET.&lt;br&gt;&lt;a href=&quot;create&quot;&gt;Créer la forme usuelle&lt;/a&gt;&#xa0;: étape initiale 1, étape 2 et étape 3, qui met Complete à TRUE.</translation>
    </message>
    <message>
        <source>Add Loop or &amp;Jump To</source>
        <translation>Ajouter une boucle ou un &amp;saut vers</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Étape %1</translation>
    </message>
    <message>
        <source>Add step %1 to %2</source>
        <translation>Ajouter l’étape %1 à %2</translation>
    </message>
    <message>
        <source>Add selection branch to %1</source>
        <translation>Ajouter une branche de sélection à %1</translation>
    </message>
    <message>
        <source>Add parallel branch to %1</source>
        <translation>Ajouter une branche parallèle à %1</translation>
    </message>
    <message>
        <source>Add jump from step %1 to step %2 in %3</source>
        <extracomment>%1 and %2 step numbers, %3 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Ajouter un saut de l’étape %1 à l’étape %2 dans %3</translation>
    </message>
    <message>
        <source>Remove step %1 from %2</source>
        <translation>Supprimer l’étape %1 de %2</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n steps from %1</source>
        <translation>
            <numerusform>Supprimer %n étape de %1</numerusform>
            <numerusform>Supprimer %n étapes de %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Remove branch from %1</source>
        <translation>Supprimer une branche de %1</translation>
    </message>
    <message>
        <source>Renumber %1</source>
        <translation>Renuméroter %1</translation>
    </message>
    <message>
        <source>Connect %1 T%2</source>
        <extracomment>%1 the GEMMA step, %2 the transition&apos;s number</extracomment>
        <translation>Relier %1 T%2</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n steps into %1</source>
        <translation>
            <numerusform>Coller %n étape dans %1</numerusform>
            <numerusform>Coller %n étapes dans %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Create GRAFCET of %1</source>
        <translation>Créer le GRAFCET de %1</translation>
    </message>
    <message>
        <source>Add Branch &amp;Ending on a Step</source>
        <translation>Ajouter une branche finissant sur une &amp;étape</translation>
    </message>
    <message>
        <source>A new branch from this step to a new step with no transition after it (an exit step)</source>
        <translation>Une nouvelle branche de cette étape vers une nouvelle étape sans transition après elle (une étape de sortie)</translation>
    </message>
    <message>
        <source>Move Branch &amp;Left</source>
        <translation>Déplacer la branche à &amp;gauche</translation>
    </message>
    <message>
        <source>Swap the branch holding this step with the one at its left</source>
        <translation>Échange la branche qui contient cette étape avec celle à sa gauche</translation>
    </message>
    <message>
        <source>Move Branch Ri&amp;ght</source>
        <translation>Déplacer la branche à &amp;droite</translation>
    </message>
    <message>
        <source>Swap the branch holding this step with the one at its right</source>
        <translation>Échange la branche qui contient cette étape avec celle à sa droite</translation>
    </message>
    <message>
        <source>Cu&amp;t Steps</source>
        <translation>Cou&amp;per les étapes</translation>
    </message>
    <message>
        <source>Add branch ending on a step at step %1 in %2</source>
        <extracomment>%1 the step the branch leaves, %2 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Ajouter une branche finissant sur une étape à l’étape %1 de %2</translation>
    </message>
    <message>
        <source>Move branch left in %1</source>
        <extracomment>%1 the GEMMA step whose GRAFCET it is</extracomment>
        <translation>Déplacer une branche à gauche dans %1</translation>
    </message>
    <message>
        <source>Move branch right in %1</source>
        <translation>Déplacer une branche à droite dans %1</translation>
    </message>
    <message>
        <source>Remove T%1 from %2</source>
        <translation>Supprimer T%1 de %2</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n transitions from %1</source>
        <translation>
            <numerusform>Supprimer %n transition de %1</numerusform>
            <numerusform>Supprimer %n transitions de %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Remove %n elements from %1</source>
        <translation>
            <numerusform>Supprimer %n élément de %1</numerusform>
            <numerusform>Supprimer %n éléments de %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Cut step %1 from %2</source>
        <translation>Couper l’étape %1 de %2</translation>
    </message>
    <message numerus="yes">
        <source>Cut %n steps from %1</source>
        <translation>
            <numerusform>Couper %n étape de %1</numerusform>
            <numerusform>Couper %n étapes de %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::GrafcetActionsModel</name>
    <message>
        <source>When</source>
        <translation>Quand</translation>
    </message>
    <message>
        <source>Qual.</source>
        <extracomment>short: the column is narrow; its tooltip says &quot;qualifier&quot; in full</extracomment>
        <translation>Qual.</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>IF / value</source>
        <extracomment>the condition after IF of an N action, or the value of a := action; short: the column is narrow</extracomment>
        <translation>IF / valeur</translation>
    </message>
    <message>
        <source>While the step is active (N), or once when it is activated or deactivated (S, R, :=)</source>
        <translation>Tant que l’étape est active (N), ou une fois à son activation ou à sa désactivation (S, R, :=)</translation>
    </message>
    <message>
        <source>Qualifier. N: the variable is TRUE while the step is active
S, R: set it TRUE or FALSE
:=: assign it the value</source>
        <translation>Qualificatif. N&#xa0;: la variable est TRUE tant que l’étape est active
S, R&#xa0;: la mettre à TRUE ou à FALSE
:=&#xa0;: lui affecter la valeur</translation>
    </message>
    <message>
        <source>An output or internal variable, or Complete</source>
        <translation>Une variable de sortie ou interne, ou Complete</translation>
    </message>
    <message>
        <source>N: only IF this condition holds (may be empty)
:=: the value assigned</source>
        <translation>N&#xa0;: seulement SI cette condition est vraie (peut être vide)
:=&#xa0;: la valeur affectée</translation>
    </message>
    <message>
        <source>While active</source>
        <translation>Tant qu’active</translation>
    </message>
    <message>
        <source>On activation</source>
        <translation>À l’activation</translation>
    </message>
    <message>
        <source>On deactivation</source>
        <translation>À la désactivation</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetSimulationMarks</name>
    <message>
        <source>%1 is active: its GRAFCET runs. Unstable: the last scan ended without a stable situation</source>
        <translation>%1 est active&#xa0;: son GRAFCET évolue. Unstable&#xa0;: le dernier cycle s&apos;est terminé sans situation stable</translation>
    </message>
    <message>
        <source>%1 has just been entered: its GRAFCET starts from its initial steps in the next scan</source>
        <translation>%1 vient d&apos;être activée&#xa0;: son GRAFCET part de ses étapes initiales au prochain cycle</translation>
    </message>
    <message>
        <source>%1 is not active: its GRAFCET is shown greyed, as it was left</source>
        <translation>%1 n&apos;est pas active&#xa0;: son GRAFCET est grisé, tel qu&apos;il a été laissé</translation>
    </message>
    <message numerus="yes">
        <source>%1 is active: its GRAFCET runs (step(s) %2)</source>
        <translation>
            <numerusform>%1 est active : son GRAFCET évolue (étape %2)</numerusform>
            <numerusform>%1 est active : son GRAFCET évolue (étapes %2)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 has just been resumed: its GRAFCET goes on where it was paused in the next scan</source>
        <translation>%1 vient d&apos;être repris : son GRAFCET continue là où il avait été suspendu au prochain cycle</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetStepDock</name>
    <message>
        <source>Nested Step</source>
        <translation>Étape imbriquée</translation>
    </message>
    <message>
        <source>Select a step in a nested GRAFCET&apos;s tab to see and edit its number, comment and actions.</source>
        <translation>Sélectionnez une étape dans l’onglet d’un GRAFCET imbriqué pour voir et modifier son numéro, son commentaire et ses actions.</translation>
    </message>
    <message>
        <source>&amp;Number:</source>
        <translation>&amp;Numéro&#xa0;:</translation>
    </message>
    <message>
        <source>Unique in this GRAFCET; its activity is X&lt;number&gt;. The transitions and the X&lt;number&gt; of the receptivities and actions follow a new number.</source>
        <translation>Unique dans ce GRAFCET&#xa0;; son activité est X&lt;numéro&gt;. Les transitions et les X&lt;numéro&gt; des réceptivités et des actions suivent un nouveau numéro.</translation>
    </message>
    <message>
        <source>&amp;Initial</source>
        <translation>&amp;Initiale</translation>
    </message>
    <message>
        <source>Active when the GEMMA state is entered (a GRAFCET needs at least one)</source>
        <translation>Active à l’entrée dans l’état GEMMA (un GRAFCET en demande au moins une)</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Commentaire&#xa0;:</translation>
    </message>
    <message>
        <source>What the machine does in this step</source>
        <translation>Ce que fait la machine dans cette étape</translation>
    </message>
    <message>
        <source>&amp;Actions:</source>
        <translation>&amp;Actions&#xa0;:</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>Add an action after the current one</source>
        <translation>Ajouter une action après l’action courante</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Remove the current action</source>
        <translation>Supprimer l’action courante</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Monter</translation>
    </message>
    <message>
        <source>Run the current action earlier</source>
        <translation>Exécuter l’action courante plus tôt</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Descendre</translation>
    </message>
    <message>
        <source>Run the current action later</source>
        <translation>Exécuter l’action courante plus tard</translation>
    </message>
    <message>
        <source>%1 step %2</source>
        <extracomment>A step of the nested GRAFCET of a GEMMA step: &quot;F1 step 3&quot;</extracomment>
        <translation>%1 étape %2</translation>
    </message>
    <message>
        <source>In the nested GRAFCET of %1 %2</source>
        <translation>Dans le GRAFCET imbriqué de %1 %2</translation>
    </message>
    <message>
        <source>%1 already has a step %2: choose another number.</source>
        <translation>%1 a déjà une étape %2&#xa0;: choisissez un autre numéro.</translation>
    </message>
    <message>
        <source>Step numbers start at 1: %1 is not a step number.</source>
        <translation>Les numéros d&apos;étape commencent à 1 : %1 n&apos;est pas un numéro d&apos;étape.</translation>
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
        <translation>Le GRAFCET de %1 dans le mode %2</translation>
    </message>
    <message>
        <source>The nested GRAFCET of %1</source>
        <translation>Le GRAFCET imbriqué de %1</translation>
    </message>
    <message>
        <source>PackML Chart</source>
        <translation>Diagramme PackML</translation>
    </message>
    <message>
        <source>GEMMA Chart</source>
        <translation>Diagramme GEMMA</translation>
    </message>
</context>
<context>
    <name>editor::GrafcetTransitionDock</name>
    <message>
        <source>Nested Transition</source>
        <translation>Transition imbriquée</translation>
    </message>
    <message>
        <source>Select a transition in a nested GRAFCET&apos;s tab to see and edit its receptivity.</source>
        <translation>Sélectionnez une transition dans l’onglet d’un GRAFCET imbriqué pour voir et modifier sa réceptivité.</translation>
    </message>
    <message>
        <source>From steps:</source>
        <translation>Depuis les étapes&#xa0;:</translation>
    </message>
    <message>
        <source>To steps:</source>
        <translation>Vers les étapes&#xa0;:</translation>
    </message>
    <message>
        <source>Click a step to select it</source>
        <translation>Cliquez sur une étape pour la sélectionner</translation>
    </message>
    <message>
        <source>&amp;Receptivity:</source>
        <translation>&amp;Réceptivité&#xa0;:</translation>
    </message>
    <message>
        <source>e.g. PartPresent AND X3, ↑Start, 5s/X2</source>
        <translation>p. ex. PartPresent AND X3, ↑Start, 5s/X2</translation>
    </message>
    <message>
        <source>Structured Text as in GEMMA conditions, plus X3 (step 3 is active), ↑a or RE a (rising edge), ↓a or FE a (falling edge), 5s/X3 (step 3 active for 5 s) and Complete.
Ctrl+Space completes a name.</source>
        <translation>Texte structuré comme dans les conditions GEMMA, plus X3 (l’étape 3 est active), ↑a ou RE a (front montant), ↓a ou FE a (front descendant), 5s/X3 (l’étape 3 est active depuis 5 s) et Complete.
Ctrl+Espace complète un nom.</translation>
    </message>
    <message>
        <source>%1 T%2</source>
        <extracomment>A transition of the nested GRAFCET of a GEMMA step: &quot;F1 T2&quot;</extracomment>
        <translation>%1 T%2</translation>
    </message>
    <message>
        <source>In the nested GRAFCET of %1 %2</source>
        <translation>Dans le GRAFCET imbriqué de %1 %2</translation>
    </message>
</context>
<context>
    <name>editor::LinkDrag</name>
    <message>
        <source>A transition cannot be linked to a transition: steps and transitions alternate</source>
        <translation>Une transition ne peut pas être liée à une transition : étapes et transitions alternent</translation>
    </message>
    <message>
        <source>Step %1 already leads to step %2</source>
        <translation>L’étape %1 mène déjà à l’étape %2</translation>
    </message>
    <message>
        <source>Step %1 already precedes T%2</source>
        <translation>L’étape %1 précède déjà T%2</translation>
    </message>
    <message>
        <source>Step %1 already follows T%2</source>
        <translation>L’étape %1 suit déjà T%2</translation>
    </message>
    <message>
        <source>Step %1 cannot be linked to itself through one transition</source>
        <translation>L’étape %1 ne peut pas être liée à elle-même par une seule transition</translation>
    </message>
    <message>
        <source>Step %1 would be linked to itself through T%2</source>
        <translation>L’étape %1 serait liée à elle-même par T%2</translation>
    </message>
    <message>
        <source>Drag onto a step or a transition to link them</source>
        <translation>Faites glisser jusqu’à une étape ou une transition pour les lier</translation>
    </message>
    <message>
        <source>Link step %1 to step %2 in %3</source>
        <translation>Lier l’étape %1 à l’étape %2 dans %3</translation>
    </message>
    <message>
        <source>Link step %1 to T%2 in %3</source>
        <translation>Lier l’étape %1 à T%2 dans %3</translation>
    </message>
    <message>
        <source>Link T%1 to step %2 in %3</source>
        <translation>Lier T%1 à l’étape %2 dans %3</translation>
    </message>
</context>
<context>
    <name>editor::MachineDock</name>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>Add a component of the kind chosen beside</source>
        <translation>Ajouter un composant du type choisi à côté</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Remove the selected component and its wiring</source>
        <translation>Supprimer le composant sélectionné et son câblage</translation>
    </message>
    <message>
        <source>The model has no machine yet. Add its components to simulate in closed loop: the machine then sets the sensors.</source>
        <translation>Le modèle n&apos;a pas encore de machine. Ajoutez ses composants pour simuler en boucle fermée : la machine positionne alors les capteurs.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>(not wired)</source>
        <translation>(non câblé)</translation>
    </message>
    <message>
        <source>A BOOL output of the program, which drives the component</source>
        <translation>Une sortie BOOL du programme, qui commande le composant</translation>
    </message>
    <message>
        <source>A BOOL input of the program, which the component sets</source>
        <translation>Une entrée BOOL du programme, que le composant positionne</translation>
    </message>
    <message>
        <source>Unlimited</source>
        <translation>Illimité</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>Contact</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(aucun)</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>Alimente</translation>
    </message>
</context>
<context>
    <name>editor::MachineTab</name>
    <message>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>The virtual machine: its components, moving as the simulation runs</source>
        <translation>La machine virtuelle : ses composants, qui bougent pendant la simulation</translation>
    </message>
</context>
<context>
    <name>editor::MainWindow</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Échec de l&apos;enregistrement automatique&#xa0;: %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;ide</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Nouveau</translation>
    </message>
    <message>
        <source>Start a new model from the GEMMA template</source>
        <translation>Commencer un nouveau modèle à partir du gabarit GEMMA</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Ouvrir…</translation>
    </message>
    <message>
        <source>Open a GG Studio model, a GG-Generator file or an exported PLCopen XML file</source>
        <translation>Ouvrir un modèle GG Studio, un fichier GG-Generator ou un fichier PLCopen XML exporté</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Enregistrer &amp;sous…</translation>
    </message>
    <message>
        <source>&amp;Reset to Template…</source>
        <translation>Réinitialiser au ga&amp;barit…</translation>
    </message>
    <message>
        <source>Put every state, transition, variable and setting back to the template</source>
        <translation>Remettre chaque état, transition, variable et paramètre comme dans le gabarit</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annuler %1</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Rétablir %1</translation>
    </message>
    <message>
        <source>&amp;Model Settings…</source>
        <translation>&amp;Paramètres du modèle…</translation>
    </message>
    <message>
        <source>Model name, PLC cycle time and code dialect</source>
        <translation>Nom du modèle, temps de cycle de l&apos;automate et dialecte du code</translation>
    </message>
    <message>
        <source>Show &amp;Hidden Elements</source>
        <translation>Afficher les éléments &amp;masqués</translation>
    </message>
    <message>
        <source>Draw the hidden states and transitions faded, so they can be selected</source>
        <translation>Dessiner en estompé les états et transitions masqués, pour pouvoir les sélectionner</translation>
    </message>
    <message>
        <source>&amp;Actual Size (100 %)</source>
        <translation>&amp;Taille réelle (100 %)</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;avant</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Zoom a&amp;rrière</translation>
    </message>
    <message>
        <source>&amp;About GG Studio</source>
        <translation>À &amp;propos de GG Studio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>À propos de &amp;Qt</translation>
    </message>
    <message>
        <source>%1[*] — GG Studio</source>
        <translation>%1[*] — GG Studio</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Modifications non enregistrées</translation>
    </message>
    <message>
        <source>The model “%1” has unsaved changes.</source>
        <translation>Le modèle «&#xa0;%1&#xa0;» contient des modifications non enregistrées.</translation>
    </message>
    <message>
        <source>Do you want to save them?</source>
        <translation>Voulez-vous les enregistrer&#xa0;?</translation>
    </message>
    <message>
        <source>All supported files (*.json *.xml)</source>
        <translation>Tous les fichiers pris en charge (*.json *.xml)</translation>
    </message>
    <message>
        <source>GG Studio models (*.json)</source>
        <translation>Modèles GG Studio (*.json)</translation>
    </message>
    <message>
        <source>GG-Generator files (*.json)</source>
        <translation>Fichiers GG-Generator (*.json)</translation>
    </message>
    <message>
        <source>GG Studio PLCopen XML (*.xml)</source>
        <translation>PLCopen XML de GG Studio (*.xml)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Open Model</source>
        <translation>Ouvrir un modèle</translation>
    </message>
    <message>
        <source>Could not open %1.</source>
        <translation>Impossible d&apos;ouvrir %1.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Ouvert&#xa0;: %1</translation>
    </message>
    <message>
        <source>Imported %1: Save As keeps it as a GG Studio model</source>
        <translation>%1 importé&#xa0;: «&#xa0;Enregistrer sous&#xa0;» le conserve comme modèle GG Studio</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>sans titre</translation>
    </message>
    <message>
        <source>Save Model As</source>
        <translation>Enregistrer le modèle sous</translation>
    </message>
    <message>
        <source>Save Model</source>
        <translation>Enregistrer le modèle</translation>
    </message>
    <message>
        <source>Could not save %1.</source>
        <translation>Impossible d&apos;enregistrer %1.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Enregistré&#xa0;: %1</translation>
    </message>
    <message>
        <source>Export Failed</source>
        <translation>Échec de l&apos;export</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>Impossible d&apos;écrire %1.</translation>
    </message>
    <message>
        <source>Recovered unsaved changes: save them to keep them</source>
        <translation>Modifications non enregistrées récupérées&#xa0;: enregistrez-les pour les conserver</translation>
    </message>
    <message>
        <source>Reset to Template</source>
        <translation>Réinitialiser au gabarit</translation>
    </message>
    <message>
        <source>Put every state, transition, variable and setting back to the GEMMA template? You can undo this.</source>
        <translation>Remettre chaque état, transition, variable et paramètre comme dans le gabarit GEMMA&#xa0;? Vous pourrez annuler cette opération.</translation>
    </message>
    <message>
        <source>About GG Studio</source>
        <translation>À propos de GG Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;GG Studio %1&lt;/h3&gt;&lt;p&gt;An editor for the GEMMA-GRAFCET method: choose the operating modes of a machine on the GEMMA template, write the conditions of their transitions, and generate the IEC 61131-3 program that runs them (Structured Text, PLCopen XML).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;GG Studio %1&lt;/h3&gt;&lt;p&gt;Un éditeur pour la méthode GEMMA-GRAFCET&#xa0;: choisissez les modes de marche et d&apos;arrêt d&apos;une machine sur le gabarit GEMMA, écrivez les réceptivités de leurs transitions et générez le programme IEC 61131-3 qui les exécute (texte structuré (ST), PLCopen XML).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Simulate</source>
        <translation>&amp;Simuler</translation>
    </message>
    <message>
        <source>Run the model scan by scan; editing is locked while the simulation is on</source>
        <translation>Exécuter le modèle cycle par cycle&#xa0;; la modification est verrouillée pendant la simulation</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Exécuter</translation>
    </message>
    <message>
        <source>Run scans at the speed set in the Simulation dock, or pause them</source>
        <translation>Exécuter les cycles à la vitesse choisie dans le panneau Simulation, ou les mettre en pause</translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation>&amp;Un cycle</translation>
    </message>
    <message>
        <source>R&amp;eset Simulation</source>
        <translation>&amp;Réinitialiser la simulation</translation>
    </message>
    <message>
        <source>Simulation: editing locked</source>
        <translation>Simulation&#xa0;: modification verrouillée</translation>
    </message>
    <message>
        <source>&amp;Verify</source>
        <translation>&amp;Vérifier</translation>
    </message>
    <message>
        <source>Verifying…</source>
        <translation>Vérification…</translation>
    </message>
    <message>
        <source>Verification failed: %1</source>
        <translation>Échec de la vérification&#xa0;: %1</translation>
    </message>
    <message>
        <source>Verification finished: some properties do not hold (see Problems)</source>
        <translation>Vérification terminée&#xa0;: certaines propriétés ne sont pas satisfaites (voir Problèmes)</translation>
    </message>
    <message>
        <source>Verification finished: every property holds</source>
        <translation>Vérification terminée&#xa0;: toutes les propriétés sont satisfaites</translation>
    </message>
    <message>
        <source>%1 counterexample</source>
        <translation>contre-exemple %1</translation>
    </message>
    <message>
        <source>Replay in Simulator</source>
        <translation>Rejouer dans le simulateur</translation>
    </message>
    <message>
        <source>Could not replay %1.</source>
        <translation>Impossible de rejouer %1.</translation>
    </message>
    <message>
        <source>E&amp;xamples</source>
        <translation>E&amp;xemples</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>&amp;Réinitialiser la disposition</translation>
    </message>
    <message>
        <source>Put the panels and the toolbar back where they were at the first start</source>
        <translation>Remettre les panneaux et la barre d&apos;outils là où ils étaient au premier démarrage</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Barre d&apos;outils principale</translation>
    </message>
    <message>
        <source>Export PLCopen XML</source>
        <translation>Exporter en PLCopen XML</translation>
    </message>
    <message>
        <source>Open Example</source>
        <translation>Ouvrir un exemple</translation>
    </message>
    <message>
        <source>Could not open the example “%1”.</source>
        <translation>Impossible d&apos;ouvrir l&apos;exemple «&#xa0;%1&#xa0;».</translation>
    </message>
    <message>
        <source>Opened the example “%1” as an untitled copy: Save As keeps your changes</source>
        <translation>Exemple «&#xa0;%1&#xa0;» ouvert comme copie sans titre&#xa0;: «&#xa0;Enregistrer sous&#xa0;» conserve vos modifications</translation>
    </message>
    <message>
        <source>&amp;Hide Selected Elements</source>
        <translation>&amp;Masquer les éléments sélectionnés</translation>
    </message>
    <message>
        <source>Hide the selected states and transitions: the machine does not need them</source>
        <translation>Masquer les états et transitions sélectionnés&#xa0;: la machine n&apos;en a pas besoin</translation>
    </message>
    <message>
        <source>Sho&amp;w Selected Elements</source>
        <translation>A&amp;fficher les éléments sélectionnés</translation>
    </message>
    <message>
        <source>Show the selected hidden states and transitions again</source>
        <translation>Afficher de nouveau les états et transitions masqués sélectionnés</translation>
    </message>
    <message>
        <source>&amp;User Guide</source>
        <translation>&amp;Guide de l&apos;utilisateur</translation>
    </message>
    <message>
        <source>How to build a model, simulate, verify and export, offline; F1 opens it at the part about the panel you are in</source>
        <translation>Comment construire un modèle, le simuler, le vérifier et l&apos;exporter, hors ligne (en anglais)&#xa0;; F1 l&apos;ouvre à la partie sur le panneau où vous êtes</translation>
    </message>
    <message>
        <source>Step &amp;Back</source>
        <translation>Cycle &amp;précédent</translation>
    </message>
    <message>
        <source>Show the previous scan of the run; a scan or Run from there continues from it and drops the later scans</source>
        <translation>Afficher le cycle précédent de l&apos;exécution&#xa0;; un cycle ou Exécuter à partir de là repart de ce cycle et abandonne les cycles suivants</translation>
    </message>
    <message>
        <source>Step &amp;Forward</source>
        <translation>Cycle suiva&amp;nt</translation>
    </message>
    <message>
        <source>Show the next scan of the run&apos;s history</source>
        <translation>Afficher le cycle suivant de l&apos;historique de l&apos;exécution</translation>
    </message>
    <message>
        <source>Prove what the GEMMA layer and the nested GRAFCETs can and cannot do for every input sequence, and check your properties; the findings go to the Problems dock</source>
        <translation>Prouver ce que le niveau GEMMA et les GRAFCET imbriqués peuvent et ne peuvent pas faire pour toute suite d&apos;entrées, et vérifier vos propriétés&#xa0;; les constats vont dans le panneau Problèmes</translation>
    </message>
    <message>
        <source>Verify with &amp;Exact Time</source>
        <translation>Vérifier avec le temps e&amp;xact</translation>
    </message>
    <message>
        <source>Count time in scans when verifying: every timer elapses exactly when the PLC&apos;s would, instead of &quot;may or may not have elapsed&quot; (more states)</source>
        <translation>Compter le temps en cycles pendant la vérification&#xa0;: chaque temporisation s&apos;écoule exactement quand celle de l&apos;automate s&apos;écoulerait, au lieu de «&#xa0;écoulée ou non&#xa0;» (plus d&apos;états)</translation>
    </message>
    <message>
        <source>%1 was opened, but not everything in the file was taken over.</source>
        <translation>%1 a été ouvert, mais tout le contenu du fichier n&apos;a pas été repris.</translation>
    </message>
    <message>
        <source>Verification finished: nothing is violated, but some properties are undecided (see Problems)</source>
        <translation>Vérification terminée : rien n&apos;est violé, mais certaines propriétés sont indécises (voir Problèmes)</translation>
    </message>
    <message>
        <source>&amp;Fit to Window</source>
        <translation>Ajuster à la &amp;fenêtre</translation>
    </message>
    <message>
        <source>Put every command, unit mode, GRAFCET, variable and setting back to a new PackML model of this edition? You can undo this.</source>
        <translation>Remettre chaque commande, mode d&apos;unité, GRAFCET, variable et réglage à ceux d&apos;un nouveau modèle PackML de cette édition ? Vous pouvez l&apos;annuler.</translation>
    </message>
    <message>
        <source>Verify with the &amp;Machine</source>
        <translation>Vérifier avec la &amp;machine</translation>
    </message>
    <message>
        <source>Explore the program with the model&apos;s machine: the sensors it drives follow the cylinders and conveyors instead of taking any value</source>
        <translation>Explorer le programme avec la machine du modèle : les capteurs qu&apos;elle pilote suivent les vérins et les convoyeurs au lieu de prendre n&apos;importe quelle valeur</translation>
    </message>
    <message>
        <source>Verification cancelled: the model, the Complete settings, the machine&apos;s use or Exact Time changed</source>
        <translation>Vérification annulée : le modèle, les réglages de Complete, l&apos;usage de la machine ou le temps exact ont changé</translation>
    </message>
    <message>
        <source>Co&amp;nnect…</source>
        <translation>Co&amp;nnecter…</translation>
    </message>
    <message>
        <source>Link the simulation to a digital twin, a soft PLC or an HMI over Modbus TCP; it then runs in real time</source>
        <translation>Relier la simulation à un jumeau numérique, un automate logiciel ou une IHM par Modbus TCP ; elle tourne alors en temps réel</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Déconnecter</translation>
    </message>
    <message>
        <source>End the Modbus TCP link</source>
        <translation>Mettre fin à la liaison Modbus TCP</translation>
    </message>
    <message>
        <source>Verify with Single &amp;Faults</source>
        <translation>Vérifier avec des &amp;défauts uniques</translation>
    </message>
    <message>
        <source>With the machine, also explore any one fault from any scan on: a sensor stuck or flickering, a cylinder or conveyor jammed</source>
        <translation>Avec la machine, explorer aussi un défaut quelconque à partir de n&apos;importe quel cycle : un capteur bloqué ou instable, un vérin ou un convoyeur coincé</translation>
    </message>
    <message>
        <source>The Modbus link is for GEMMA models; PackML models are not linked yet</source>
        <translation>La liaison Modbus est pour les modèles GEMMA ; les modèles PackML ne sont pas encore reliés</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Connecter</translation>
    </message>
    <message>
        <source>The Modbus link could not start: %1</source>
        <translation>La liaison Modbus n&apos;a pas pu démarrer : %1</translation>
    </message>
    <message>
        <source>Undo</source>
        <extracomment>the Undo button of the toolbar (the Edit menu names the command)</extracomment>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Redo</source>
        <extracomment>the Redo button of the toolbar (the Edit menu names the command)</extracomment>
        <translation>Rétablir</translation>
    </message>
    <message>
        <source>Undo %1</source>
        <translation>Annuler %1</translation>
    </message>
    <message>
        <source>Redo %1</source>
        <translation>Rétablir %1</translation>
    </message>
</context>
<context>
    <name>editor::ModbusConnectDialog</name>
    <message>
        <source>Coil</source>
        <translation>Bobine</translation>
    </message>
    <message>
        <source>Discrete input</source>
        <translation>Entrée discrète</translation>
    </message>
    <message>
        <source>Holding register</source>
        <translation>Registre de maintien</translation>
    </message>
    <message>
        <source>Input register</source>
        <translation>Registre d&apos;entrée</translation>
    </message>
    <message>
        <source>Connect over Modbus TCP</source>
        <translation>Connecter par Modbus TCP</translation>
    </message>
    <message>
        <source>Server: the twin connects to the simulator</source>
        <translation>Serveur : le jumeau se connecte au simulateur</translation>
    </message>
    <message>
        <source>Client: the simulator connects to the twin</source>
        <translation>Client : le simulateur se connecte au jumeau</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Table</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Mode :</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>Hôte :</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Port :</translation>
    </message>
    <message>
        <source>Unit id:</source>
        <translation>Identifiant d&apos;unité :</translation>
    </message>
    <message>
        <source>Load CSV…</source>
        <translation>Charger un CSV…</translation>
    </message>
    <message>
        <source>Save As CSV…</source>
        <translation>Enregistrer en CSV…</translation>
    </message>
    <message>
        <source>Default Map</source>
        <translation>Table par défaut</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Connecter</translation>
    </message>
    <message>
        <source>Map (each table numbered from 0 in declaration order unless loaded):</source>
        <translation>Table d&apos;adresses (chaque table numérotée à partir de 0 dans l&apos;ordre de déclaration, sauf si elle est chargée) :</translation>
    </message>
    <message>
        <source>Load Modbus Map</source>
        <translation>Charger une table Modbus</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Fichiers CSV (*.csv)</translation>
    </message>
    <message>
        <source>Save Modbus Map</source>
        <translation>Enregistrer la table Modbus</translation>
    </message>
    <message>
        <source>Line %1, column %2: %3</source>
        <translation>Ligne %1, colonne %2 : %3</translation>
    </message>
    <message>
        <source>%1 cannot be used:</source>
        <translation>%1 ne peut pas être utilisé :</translation>
    </message>
    <message>
        <source>%1 could not be saved: %2</source>
        <translation>%1 n&apos;a pas pu être enregistré : %2</translation>
    </message>
</context>
<context>
    <name>editor::ModbusConnection</name>
    <message>
        <source>The simulation could not start.</source>
        <translation>La simulation n&apos;a pas pu démarrer.</translation>
    </message>
    <message>
        <source>Modbus server on %1, unit %2, clients connected: %3</source>
        <translation>Serveur Modbus sur %1, unité %2, clients connectés : %3</translation>
    </message>
    <message>
        <source>Modbus client of %1: connected</source>
        <translation>Client Modbus de %1 : connecté</translation>
    </message>
    <message>
        <source>Modbus client of %1: connecting</source>
        <translation>Client Modbus de %1 : connexion en cours</translation>
    </message>
    <message>
        <source>Modbus client of %1: not connected, trying again</source>
        <translation>Client Modbus de %1 : non connecté, nouvel essai</translation>
    </message>
    <message>
        <source>Set by the twin: %1</source>
        <translation>Mis par le jumeau : %1</translation>
    </message>
    <message>
        <source>Errors: %1, the last: %2</source>
        <translation>Erreurs : %1, la dernière : %2</translation>
    </message>
</context>
<context>
    <name>editor::ModelCommand</name>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 is the edit (&quot;Rename variable Stop to Halt&quot;), %2 why the model refused it</extracomment>
        <translation>%1&#xa0;: %2</translation>
    </message>
</context>
<context>
    <name>editor::ModelSettingsDialog</name>
    <message>
        <source>Model Settings</source>
        <translation>Paramètres du modèle</translation>
    </message>
    <message>
        <source>The project name written into the exported PLCopen XML</source>
        <translation>Le nom du projet écrit dans le PLCopen XML exporté</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>The period of the cyclic PLC task that runs GEMMA</source>
        <translation>La période de la tâche cyclique de l&apos;automate qui exécute GEMMA</translation>
    </message>
    <message>
        <source>The flavour of the generated Structured Text and its preview</source>
        <translation>La variante du texte structuré (ST) généré et de son aperçu</translation>
    </message>
    <message>
        <source>Use the cycle time and dialect for &amp;new models</source>
        <translation>Utiliser ce temps de cycle et ce dialecte pour les nou&amp;veaux modèles</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Nom&#xa0;:</translation>
    </message>
    <message>
        <source>PLC &amp;cycle time:</source>
        <translation>Temps de &amp;cycle de l&apos;automate&#xa0;:</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialecte&#xa0;:</translation>
    </message>
    <message>
        <source>Change model settings</source>
        <translation>Modifier les paramètres du modèle</translation>
    </message>
    <message>
        <source>One evolution per scan</source>
        <translation>Une évolution par cycle</translation>
    </message>
    <message>
        <source>Until stable</source>
        <translation>Jusqu&apos;à stabilité</translation>
    </message>
    <message>
        <source>How a nested GRAFCET evolves in one call of its function block</source>
        <translation>Comment un GRAFCET imbriqué évolue en un appel de son bloc fonctionnel</translation>
    </message>
    <message>
        <source>&amp;Evolution rule:</source>
        <translation>&amp;Règle d&apos;évolution&#xa0;:</translation>
    </message>
    <message>
        <source>Each scan repeats evolutions until no transition can fire (IEC 60848&apos;s search for stability), at most one more than the GRAFCET has transitions; if the last one still fires, the function block reports Unstable.</source>
        <translation>Chaque cycle répète les évolutions jusqu&apos;à ce qu&apos;aucune transition ne puisse être franchie (la recherche de stabilité de l&apos;IEC 60848), au plus une de plus que le GRAFCET n&apos;a de transitions&#xa0;; si la dernière franchit encore, le bloc fonctionnel signale Unstable.</translation>
    </message>
    <message>
        <source>Each scan fires the transitions enabled at its start once, as SFC runtimes such as CODESYS do.</source>
        <translation>Chaque cycle franchit une fois les transitions validées à son début, comme le font les exécutifs SFC tels que CODESYS.</translation>
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
        <translation>Le guide GEMMA (procédures d&apos;arrêt, de fonctionnement et de défaillance) avec un GRAFCET imbriqué dans chaque macro-étape : la méthode GEMMA-GRAFCET.</translation>
    </message>
    <message>
        <source>PackML, 2015 edition</source>
        <translation>PackML, édition 2015</translation>
    </message>
    <message>
        <source>The ISA-TR88.00.02-2015 state machine with unit modes: Production, Maintenance and Manual, a GRAFCET in each acting state.</source>
        <translation>La machine à états ISA-TR88.00.02-2015 avec ses modes d&apos;unité : Production, Maintenance et Manual, un GRAFCET dans chaque état actif.</translation>
    </message>
    <message>
        <source>PackML, 2022 edition</source>
        <translation>PackML, édition 2022</translation>
    </message>
    <message>
        <source>The ISA-TR88.00.02-2022 state machine: as 2015, with the Complete command that ends Execute.</source>
        <translation>La machine à états ISA-TR88.00.02-2022 : comme 2015, avec la commande Complete qui termine Execute.</translation>
    </message>
    <message>
        <source>New Model</source>
        <translation>Nouveau modèle</translation>
    </message>
    <message>
        <source>Which chart does the new model fill in?</source>
        <translation>Quel diagramme le nouveau modèle remplit-il ?</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartContextMenu</name>
    <message>
        <source>&amp;Open GRAFCET</source>
        <translation>&amp;Ouvrir le GRAFCET</translation>
    </message>
    <message>
        <source>&amp;Choose Its GRAFCET…</source>
        <translation>&amp;Choisir son GRAFCET…</translation>
    </message>
    <message>
        <source>Its own GRAFCET in this mode, the one of another mode, or none</source>
        <translation>Son propre GRAFCET dans ce mode, celui d&apos;un autre mode, ou aucun</translation>
    </message>
    <message>
        <source>Edit the %1 &amp;Condition…</source>
        <translation>Modifier la &amp;condition de %1…</translation>
    </message>
    <message>
        <source>Show in &amp;Mode</source>
        <translation>Afficher dans le &amp;mode</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartTexts</name>
    <message>
        <source>Disabled in mode %1: never active there.</source>
        <extracomment>%1: the unit mode the chart shows (&quot;3 Manual&quot;)</extracomment>
        <translation>Désactivé dans le mode %1 : jamais actif dans ce mode.</translation>
    </message>
    <message>
        <source>Runs its own nested GRAFCET in this mode.</source>
        <translation>Exécute son propre GRAFCET imbriqué dans ce mode.</translation>
    </message>
    <message>
        <source>Runs the nested GRAFCET of mode %1 for this state.</source>
        <extracomment>%1: the number of the unit mode whose GRAFCET runs</extracomment>
        <translation>Exécute le GRAFCET imbriqué du mode %1 pour cet état.</translation>
    </message>
    <message>
        <source>No nested GRAFCET in this mode: it waits for a command.</source>
        <translation>Pas de GRAFCET imbriqué dans ce mode : il attend une commande.</translation>
    </message>
    <message>
        <source>No nested GRAFCET in this mode: it completes at once.</source>
        <translation>Pas de GRAFCET imbriqué dans ce mode : il se termine aussitôt.</translation>
    </message>
    <message>
        <source>SC (State Complete): %1 has done its work.</source>
        <extracomment>%1: a PackML state (&quot;Starting&quot;)</extracomment>
        <translation>SC (State Complete) : %1 a terminé son travail.</translation>
    </message>
    <message>
        <source>Optional: exists only under an option of Model Settings.</source>
        <translation>Facultative : n&apos;existe qu&apos;avec une option des paramètres du modèle.</translation>
    </message>
    <message>
        <source>In mode %1, %2 is disabled: this transition leads to %3.</source>
        <extracomment>%1: the unit mode (&quot;3 Manual&quot;), %2: the disabled state, %3: where the transition leads instead</extracomment>
        <translation>Dans le mode %1, %2 est désactivé : cette transition mène à %3.</translation>
    </message>
    <message>
        <source>Accepted by every state in the Abort frame, before their own transitions.</source>
        <translation>Acceptée par tous les états du cadre Abort, avant leurs propres transitions.</translation>
    </message>
    <message>
        <source>Accepted by every state in the Stop frame, before their own transitions.</source>
        <translation>Acceptée par tous les états du cadre Stop, avant leurs propres transitions.</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Condition :</translation>
    </message>
</context>
<context>
    <name>editor::PackmlChartView</name>
    <message>
        <source>Unit &amp;mode:</source>
        <translation>&amp;Mode de l&apos;unité :</translation>
    </message>
    <message>
        <source>The unit mode the chart shows: its disabled states greyed, its skipped transitions labelled with where they lead</source>
        <translation>Le mode de l&apos;unité que montre le diagramme : ses états désactivés grisés, ses transitions sautées étiquetées avec leur destination</translation>
    </message>
</context>
<context>
    <name>editor::PackmlCommandsDock</name>
    <message>
        <source>Commands</source>
        <translation>Commandes</translation>
    </message>
    <message>
        <source>Commands belong to PackML models: this model follows GEMMA.</source>
        <translation>Les commandes concernent les modèles PackML : ce modèle suit le GEMMA.</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>a PackML command&apos;s row: its PackTags number and name, &quot;4 Hold&quot;</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Condition :</translation>
    </message>
    <message>
        <source>e.g. %1, or FALSE for a command given only through CntrlCmd</source>
        <translation>p. ex. %1, ou FALSE pour une commande donnée seulement par CntrlCmd</translation>
    </message>
    <message>
        <source>Issues the command at its rising edge. Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND, XOR, OR, comparisons.
Ctrl+Space completes a variable name.</source>
        <translation>Donne la commande à son front montant. Texte structuré : variables déclarées, nombres, TRUE, FALSE, NOT, AND, XOR, OR, comparaisons.
Ctrl+Espace complète un nom de variable.</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Commentaire :</translation>
    </message>
    <message>
        <source>Where the command comes from on this machine</source>
        <translation>D&apos;où vient la commande sur cette machine</translation>
    </message>
</context>
<context>
    <name>editor::PackmlModeForm</name>
    <message>
        <source>Name:</source>
        <translation>Nom :</translation>
    </message>
    <message>
        <source>User modes (4 to 31) take an IEC identifier that no other mode has and the generated code does not use; it becomes part of function block names.
Modes 1 to 3 are Production, Maintenance and Manual.</source>
        <translation>Les modes utilisateur (4 à 31) prennent un identificateur CEI qu&apos;aucun autre mode n&apos;a et que le code généré n&apos;utilise pas ; il entre dans les noms des blocs fonctionnels.
Les modes 1 à 3 sont Production, Maintenance et Manual.</translation>
    </message>
    <message>
        <source>Comment:</source>
        <translation>Commentaire :</translation>
    </message>
    <message>
        <source>What the unit does in this mode</source>
        <translation>Ce que fait l&apos;unité dans ce mode</translation>
    </message>
    <message>
        <source>Request condition:</source>
        <translation>Condition de demande :</translation>
    </message>
    <message>
        <source>None: requested through UnitMode only (e.g. KeyManual)</source>
        <translation>Aucune : demandé seulement par UnitMode (p. ex. KeyManual)</translation>
    </message>
    <message>
        <source>Requests this mode at its rising edge, as a rising edge of UnitModeChangeRequest with UnitMode set to its number does.</source>
        <translation>Demande ce mode à son front montant, comme le fait un front montant de UnitModeChangeRequest avec UnitMode à son numéro.</translation>
    </message>
    <message>
        <source>Disabled states</source>
        <translation>États désactivés</translation>
    </message>
    <message>
        <source>Stopped, Idle, Execute and Aborted are never disabled. Disabling Held, Suspended or Complete disables the acting states of its loop; enabling one of those enables it again.</source>
        <translation>Stopped, Idle, Execute et Aborted ne sont jamais désactivés. Désactiver Held, Suspended ou Complete désactive les états actifs de sa boucle ; en activer un le réactive.</translation>
    </message>
    <message>
        <source>Mode change allowed in</source>
        <translation>Changement de mode permis en</translation>
    </message>
    <message>
        <source>A change to or from this mode is granted in a state that both modes list and the requested mode enables.</source>
        <translation>Un changement vers ou depuis ce mode est accordé dans un état que les deux modes listent et que le mode demandé active.</translation>
    </message>
    <message>
        <source>%1 is disabled in this mode: no change can be granted there.</source>
        <translation>%1 est désactivé dans ce mode : aucun changement ne peut y être accordé.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlModesDock</name>
    <message>
        <source>Modes</source>
        <translation>Modes</translation>
    </message>
    <message>
        <source>Unit modes belong to PackML models: this model follows GEMMA.</source>
        <translation>Les modes d&apos;unité concernent les modèles PackML : ce modèle suit le GEMMA.</translation>
    </message>
    <message>
        <source>The number of the next user mode (PackTags UnitMode)</source>
        <translation>Le numéro du prochain mode utilisateur (PackTags UnitMode)</translation>
    </message>
    <message>
        <source>&amp;Add Mode</source>
        <translation>&amp;Ajouter un mode</translation>
    </message>
    <message>
        <source>Adds a user mode with this number: every state enabled, mode changes in Stopped, Idle and Aborted</source>
        <translation>Ajoute un mode utilisateur de ce numéro : tous les états activés, changements de mode en Stopped, Idle et Aborted</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <source>&amp;Initial mode:</source>
        <translation>Mode &amp;initial :</translation>
    </message>
    <message>
        <source>The mode the unit is in at power-up</source>
        <translation>Le mode de l&apos;unité à la mise sous tension</translation>
    </message>
    <message>
        <source>Production is the mode every unit has</source>
        <translation>Production est le mode que toute unité possède</translation>
    </message>
    <message>
        <source>Removes the mode with its GRAFCETs</source>
        <translation>Supprime le mode avec ses GRAFCET</translation>
    </message>
</context>
<context>
    <name>editor::PackmlSettingsWidget</name>
    <message>
        <source>&amp;Hold accepted in Suspended</source>
        <translation>&amp;Hold accepté en Suspended</translation>
    </message>
    <message>
        <source>Suspended → Holding on Hold, an optional transition of the 2015 model and a standard one of 2022</source>
        <translation>Suspended → Holding sur Hold, une transition facultative du modèle 2015 et standard en 2022</translation>
    </message>
    <message>
        <source>C&amp;omplete accepted in Suspended and Held</source>
        <translation>C&amp;omplete accepté en Suspended et Held</translation>
    </message>
    <message>
        <source>Suspended and Held → Completing on the Complete command (2022 edition only)</source>
        <translation>Suspended et Held → Completing sur la commande Complete (édition 2022 seulement)</translation>
    </message>
    <message>
        <source>The state at power-up: Stopped as usual, Aborted for a unit that must be cleared after a power loss, Idle for one with nothing to reset</source>
        <translation>L&apos;état à la mise sous tension : Stopped d&apos;habitude, Aborted pour une unité à acquitter après une coupure de courant, Idle pour une unité sans rien à réinitialiser</translation>
    </message>
    <message>
        <source>PackML &amp;edition:</source>
        <translation>&amp;Édition PackML :</translation>
    </message>
    <message>
        <source>Initial &amp;state:</source>
        <translation>É&amp;tat initial :</translation>
    </message>
    <message>
        <source>2022: Execute is left on the Complete command, which a new model conditions on Cmd_Complete; its State Complete leads nowhere.</source>
        <translation>2022 : Execute se quitte sur la commande Complete, qu&apos;un nouveau modèle conditionne par Cmd_Complete ; son State Complete ne mène nulle part.</translation>
    </message>
    <message>
        <source>2015: Execute&apos;s State Complete leads to Completing; there is no Complete command.</source>
        <translation>2015 : le State Complete d&apos;Execute mène à Completing ; il n&apos;y a pas de commande Complete.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlSimulationDock</name>
    <message>
        <source>PackML Simulation</source>
        <translation>Simulation PackML</translation>
    </message>
    <message>
        <source>Start Simulation</source>
        <translation>Démarrer la simulation</translation>
    </message>
    <message>
        <source>Run or pause the scans</source>
        <translation>Lancer ou suspendre les cycles</translation>
    </message>
    <message>
        <source>Single scan</source>
        <translation>Un seul cycle</translation>
    </message>
    <message>
        <source>Step back: show the scan before</source>
        <translation>Reculer : afficher le cycle précédent</translation>
    </message>
    <message>
        <source>Step forward: show the scan after</source>
        <translation>Avancer : afficher le cycle suivant</translation>
    </message>
    <message>
        <source>Reset: the initial state and mode, inputs at their defaults</source>
        <translation>Réinitialiser : l&apos;état et le mode initiaux, les entrées à leurs valeurs par défaut</translation>
    </message>
    <message>
        <source>End the simulation</source>
        <translation>Terminer la simulation</translation>
    </message>
    <message>
        <source>Scans/s:</source>
        <translation>Cycles/s :</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unité</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>Trace</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Scénario</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>Commandes</translation>
    </message>
    <message>
        <source>Unit mode</source>
        <translation>Mode de l&apos;unité</translation>
    </message>
    <message>
        <source>Pick a mode to request it: the mode manager grants it or says why not</source>
        <translation>Choisissez un mode pour le demander : le gestionnaire de modes l&apos;accorde ou dit pourquoi non</translation>
    </message>
    <message>
        <source>Function block</source>
        <translation>Bloc fonctionnel</translation>
    </message>
    <message>
        <source>SC from the skeleton</source>
        <extracomment>the State Complete of a state without nested GRAFCET: as the generated skeleton sets it</extracomment>
        <translation>SC du squelette</translation>
    </message>
    <message>
        <source>SC = TRUE (by hand)</source>
        <translation>SC = TRUE (à la main)</translation>
    </message>
    <message>
        <source>SC = FALSE (by hand)</source>
        <translation>SC = FALSE (à la main)</translation>
    </message>
    <message>
        <source>The State Complete of a state without nested GRAFCET, set by hand to hold an acting state or to complete Execute</source>
        <translation>Le State Complete d&apos;un état sans GRAFCET imbriqué, affecté à la main pour retenir un état actif ou terminer Execute</translation>
    </message>
    <message>
        <source>Replay Scenario…</source>
        <translation>Rejouer un scénario…</translation>
    </message>
    <message>
        <source>Start the simulation to play the unit&apos;s commands and modes.</source>
        <translation>Démarrez la simulation pour jouer les commandes et les modes de l&apos;unité.</translation>
    </message>
    <message>
        <source>Scan %1: %2 in %3</source>
        <extracomment>%1: a scan number, %2: a PackML state (Execute), %3: a unit mode (Production)</extracomment>
        <translation>Cycle %1 : %2 en %3</translation>
    </message>
    <message>
        <source>%1 (history; the latest scan is %2)</source>
        <extracomment>%1: a status, %2: the latest scan</extracomment>
        <translation>%1 (historique ; le dernier cycle est %2)</translation>
    </message>
    <message>
        <source>%1 is accepted in %2</source>
        <translation>%1 est accepté dans %2</translation>
    </message>
    <message>
        <source>%1 is not accepted in %2: pressing it shows why</source>
        <translation>%1 n&apos;est pas accepté dans %2 : l&apos;appuyer montre pourquoi</translation>
    </message>
    <message>
        <source>%1: requested, read by the next scan</source>
        <translation>%1 : demandé, lu par le prochain cycle</translation>
    </message>
    <message>
        <source>%1 is a wait state: no function block runs in it</source>
        <translation>%1 est un état d&apos;attente : aucun bloc fonctionnel ne s&apos;y exécute</translation>
    </message>
    <message>
        <source>%1: active steps %2, Complete = %3</source>
        <extracomment>%1: a function block instance (Production_Execute), %2: step numbers, %3: TRUE or FALSE</extracomment>
        <translation>%1 : étapes actives %2, Complete = %3</translation>
    </message>
    <message>
        <source>%1 runs no GRAFCET: Complete = %2</source>
        <translation>%1 n&apos;exécute aucun GRAFCET : Complete = %2</translation>
    </message>
    <message>
        <source>Replaying %1: scan %2 of %3</source>
        <extracomment>%1: a scenario file, %2: the scan shown, %3: its last scan</extracomment>
        <translation>Rejeu de %1 : cycle %2 sur %3</translation>
    </message>
    <message>
        <source>%1 passed: all %2 expectation(s) met</source>
        <translation>%1 réussi : les %2 attente(s) sont satisfaites</translation>
    </message>
    <message>
        <source>%1 failed: %2 of %3 expectation(s) did not hold</source>
        <translation>%1 échoué : %2 attente(s) sur %3 non satisfaites</translation>
    </message>
    <message>
        <source>Cannot replay %1:
%2</source>
        <translation>Impossible de rejouer %1 :
%2</translation>
    </message>
    <message>
        <source>Replay Scenario</source>
        <translation>Rejouer un scénario</translation>
    </message>
    <message>
        <source>Scenarios (*.scenario *.txt);;All files (*)</source>
        <translation>Scénarios (*.scenario *.txt);;Tous les fichiers (*)</translation>
    </message>
</context>
<context>
    <name>editor::PackmlStateDock</name>
    <message>
        <source>State</source>
        <translation>État</translation>
    </message>
    <message>
        <source>Select a state in the PackML chart to see what it means and what runs in it.</source>
        <translation>Sélectionnez un état dans le diagramme PackML pour voir ce qu&apos;il signifie et ce qui s&apos;y exécute.</translation>
    </message>
    <message>
        <source>Nested GRAFCET per mode</source>
        <translation>GRAFCET imbriqué par mode</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>a PackML state&apos;s title: its PackTags number and name, &quot;6 Execute&quot;</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Own: a nested GRAFCET for this mode; Same as: the one of another mode; None: the state&apos;s skeleton (%1).</source>
        <translation>Propre : un GRAFCET imbriqué pour ce mode ; Identique à : celui d&apos;un autre mode ; Aucun : le squelette de l&apos;état (%1).</translation>
    </message>
    <message>
        <source>Execute waits for a command</source>
        <translation>Execute attend une commande</translation>
    </message>
    <message>
        <source>the state completes at once</source>
        <translation>l&apos;état se termine aussitôt</translation>
    </message>
    <message>
        <source>A wait state runs no GRAFCET.</source>
        <translation>Un état d&apos;attente n&apos;exécute aucun GRAFCET.</translation>
    </message>
    <message>
        <source>Open GRAFCET</source>
        <translation>Ouvrir le GRAFCET</translation>
    </message>
    <message>
        <source>None (skeleton)</source>
        <translation>Aucun (squelette)</translation>
    </message>
    <message>
        <source>Own GRAFCET</source>
        <translation>GRAFCET propre</translation>
    </message>
    <message>
        <source>Same as %1</source>
        <translation>Identique à %1</translation>
    </message>
    <message>
        <source>Same as mode %1 (no GRAFCET there)</source>
        <translation>Identique au mode %1 (sans GRAFCET)</translation>
    </message>
    <message>
        <source>%1 is disabled in this mode: nothing runs there.</source>
        <translation>%1 est désactivé dans ce mode : rien ne s&apos;y exécute.</translation>
    </message>
</context>
<context>
    <name>editor::PackmlTraceModel</name>
    <message>
        <source>mode %1 → %2</source>
        <extracomment>a unit mode change in one scan: from, to</extracomment>
        <translation>mode %1 → %2</translation>
    </message>
    <message>
        <source>Execute resumed</source>
        <translation>Execute repris</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Cycle</translation>
    </message>
    <message>
        <source>State</source>
        <translation>État</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <source>Fired</source>
        <translation>Franchie</translation>
    </message>
    <message>
        <source>Dropped</source>
        <translation>Ignorés</translation>
    </message>
</context>
<context>
    <name>editor::PackmlVariablesPanel</name>
    <message>
        <source>Inputs</source>
        <translation>Entrées</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Sorties</translation>
    </message>
</context>
<context>
    <name>editor::ProblemCounter</name>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n erreur</numerusform>
            <numerusform>%n erreurs</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n avertissement</numerusform>
            <numerusform>%n avertissements</numerusform>
        </translation>
    </message>
    <message>
        <source>Show the Problems panel</source>
        <translation>Afficher le panneau Problèmes</translation>
    </message>
    <message>
        <source>No problems</source>
        <translation>Aucun problème</translation>
    </message>
    <message numerus="yes">
        <source>Verification (outdated): %n finding(s)</source>
        <extracomment>the verification&apos;s findings after the checks&apos; problems in the status bar</extracomment>
        <translation>
            <numerusform>Vérification (périmée)&#xa0;: %n constat</numerusform>
            <numerusform>Vérification (périmée)&#xa0;: %n constats</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Verification: %n finding(s)</source>
        <translation>
            <numerusform>Vérification&#xa0;: %n constat</numerusform>
            <numerusform>Vérification&#xa0;: %n constats</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::ProblemsDock</name>
    <message>
        <source>Model</source>
        <translation>Modèle</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Problèmes</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Élément</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copier</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>1 erreur</translation>
    </message>
    <message numerus="yes">
        <source>%n errors</source>
        <translation>
            <numerusform>%n erreur</numerusform>
            <numerusform>%n erreurs</numerusform>
        </translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 avertissement</translation>
    </message>
    <message numerus="yes">
        <source>%n warnings</source>
        <translation>
            <numerusform>%n avertissement</numerusform>
            <numerusform>%n avertissements</numerusform>
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
            <numerusform>%n infos</numerusform>
        </translation>
    </message>
    <message>
        <source>Show or hide the errors</source>
        <translation>Afficher ou masquer les erreurs</translation>
    </message>
    <message>
        <source>Show or hide the warnings</source>
        <translation>Afficher ou masquer les avertissements</translation>
    </message>
    <message>
        <source>Show or hide the information messages</source>
        <translation>Afficher ou masquer les messages d&apos;information</translation>
    </message>
    <message>
        <source>Checks (%1)</source>
        <translation>Contrôles (%1)</translation>
    </message>
    <message>
        <source>Verification</source>
        <translation>Vérification</translation>
    </message>
    <message>
        <source>Verification (outdated)</source>
        <translation>Vérification (périmée)</translation>
    </message>
    <message>
        <source>Verification (%1)</source>
        <translation>Vérification (%1)</translation>
    </message>
    <message>
        <source>%1 step %2</source>
        <extracomment>A step of the nested GRAFCET of a GEMMA step: &quot;F1 step 3&quot;</extracomment>
        <translation>%1 étape %2</translation>
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
        <translation>GRAFCET imbriqué de %1 : 1 problème</translation>
    </message>
    <message numerus="yes">
        <source>Nested GRAFCET of %1: %n problems</source>
        <translation>
            <numerusform>GRAFCET imbriqué de %1 : %n problème</numerusform>
            <numerusform>GRAFCET imbriqué de %1 : %n problèmes</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>machine component %1</source>
        <extracomment>A component of the virtual machine: &quot;machine component Clamp&quot;</extracomment>
        <translation>composant machine %1</translation>
    </message>
</context>
<context>
    <name>editor::PropertiesPanel</name>
    <message>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <source>Add Property</source>
        <translation>Ajouter une propriété</translation>
    </message>
    <message>
        <source>Add a property after the current one (Insert)</source>
        <translation>Ajouter une propriété après la courante (Inser)</translation>
    </message>
    <message>
        <source>Remove Property</source>
        <translation>Supprimer la propriété</translation>
    </message>
    <message>
        <source>Remove the current property (Delete)</source>
        <translation>Supprimer la propriété courante (Suppr)</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Monter</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Descendre</translation>
    </message>
    <message>
        <source>&amp;Property:</source>
        <translation>&amp;Propriété&#xa0;:</translation>
    </message>
    <message>
        <source>never A_Plus AND A_Minus</source>
        <translation>never A_Plus AND A_Minus</translation>
    </message>
    <message>
        <source>Write never P or always P, where P is a condition over the variables that may also use in S (the GEMMA step S is active), S.Xn (step n of S&apos;s nested GRAFCET is active) and a -&gt; b (if a then b). Verify (F7) proves or refutes each one.</source>
        <translation>Écrivez never P ou always P, où P est une condition sur les variables qui peut aussi utiliser in S (l&apos;étape GEMMA S est active), S.Xn (l&apos;étape n du GRAFCET imbriqué de S est active) et a -&gt; b (si a alors b). Vérifier (F7) prouve ou réfute chacune.</translation>
    </message>
</context>
<context>
    <name>editor::PropertiesTableModel</name>
    <message>
        <source>Property</source>
        <translation>Propriété</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Commentaire</translation>
    </message>
</context>
<context>
    <name>editor::RecentFiles</name>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Fichiers &amp;récents</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>&amp;Vider le menu</translation>
    </message>
</context>
<context>
    <name>editor::SimulationDock</name>
    <message>
        <source>fires in the next scan</source>
        <translation>franchie au prochain cycle</translation>
    </message>
    <message>
        <source>condition FALSE</source>
        <translation>réceptivité FALSE</translation>
    </message>
    <message>
        <source>waits for Complete</source>
        <translation>attend Complete</translation>
    </message>
    <message>
        <source>preempted by %1</source>
        <translation>devancée par %1</translation>
    </message>
    <message>
        <source>condition unusable (always FALSE)</source>
        <translation>réceptivité inutilisable (toujours FALSE)</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>The simulation runs the model scan by scan, as the generated program runs on the PLC: play the inputs, watch the active step and see why each transition fires or not. Editing is locked while it runs.</source>
        <translation>La simulation exécute le modèle cycle par cycle, comme le programme généré s&apos;exécute sur l&apos;automate&#xa0;: agissez sur les entrées, suivez l&apos;étape active et voyez pourquoi chaque transition est franchie ou non. La modification est verrouillée pendant la simulation.</translation>
    </message>
    <message>
        <source>Start Simulation</source>
        <translation>Démarrer la simulation</translation>
    </message>
    <message>
        <source>Explanation</source>
        <translation>Explication</translation>
    </message>
    <message>
        <source>Trace</source>
        <translation>Trace</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Scénario</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Exécuter</translation>
    </message>
    <message>
        <source>Run scans at the chosen speed; press again to pause</source>
        <translation>Exécuter les cycles à la vitesse choisie&#xa0;; appuyez de nouveau pour mettre en pause</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Cycle</translation>
    </message>
    <message>
        <source>Run a single scan</source>
        <translation>Exécuter un seul cycle</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Réinitialiser</translation>
    </message>
    <message>
        <source>Back to the initial step, the inputs to their defaults; clears the trace</source>
        <translation>Retour à l&apos;étape initiale, entrées à leur valeur initiale&#xa0;; efface la trace</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Terminer</translation>
    </message>
    <message>
        <source>End the simulation and unlock editing</source>
        <translation>Terminer la simulation et déverrouiller la modification</translation>
    </message>
    <message>
        <source>&amp;Speed:</source>
        <translation>&amp;Vitesse&#xa0;:</translation>
    </message>
    <message>
        <source> scans/s</source>
        <translation> cycles/s</translation>
    </message>
    <message>
        <source>Scans per second (the model&apos;s cycle time only sets the simulated time)</source>
        <translation>Cycles par seconde (le temps de cycle du modèle ne fixe que le temps simulé)</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transition</translation>
    </message>
    <message>
        <source>Next scan</source>
        <translation>Prochain cycle</translation>
    </message>
    <message>
        <source>&amp;Record as Scenario…</source>
        <translation>&amp;Enregistrer comme scénario…</translation>
    </message>
    <message>
        <source>Re&amp;play Scenario…</source>
        <translation>&amp;Rejouer un scénario…</translation>
    </message>
    <message>
        <source>Run a scenario file from the initial step and check its expectations</source>
        <translation>Exécuter un fichier de scénario depuis l&apos;étape initiale et vérifier ses attentes</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Entrées</translation>
    </message>
    <message>
        <source>The model declares no variables.</source>
        <translation>Le modèle ne déclare aucune variable.</translation>
    </message>
    <message>
        <source>Complete of nested steps</source>
        <translation>Complete des étapes à comportement imbriqué</translation>
    </message>
    <message>
        <source>Automatic: the skeleton function block completes at once. Manual: you play the nested behaviour and set Complete yourself.</source>
        <translation>Automatique&#xa0;: le bloc fonctionnel squelette se termine aussitôt. Manuel&#xa0;: vous jouez le comportement imbriqué et fixez Complete vous-même.</translation>
    </message>
    <message>
        <source>Switch %1 between TRUE and FALSE</source>
        <translation>Basculer %1 entre TRUE et FALSE</translation>
    </message>
    <message>
        <source>Press</source>
        <translation>Appuyer</translation>
    </message>
    <message>
        <source>TRUE while held down, like a push button (for at least one scan)</source>
        <translation>TRUE tant qu&apos;il est enfoncé, comme un bouton-poussoir (au moins un cycle)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatique</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>Manuel</translation>
    </message>
    <message>
        <source>How %1&apos;s function block sets Complete</source>
        <translation>Comment le bloc fonctionnel de %1 fixe Complete</translation>
    </message>
    <message>
        <source>Complete</source>
        <translation>Complete</translation>
    </message>
    <message>
        <source>The value the nested behaviour gives Complete (manual mode)</source>
        <translation>La valeur que le comportement imbriqué donne à Complete (mode manuel)</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Scan %1 · %2 s</source>
        <translation>Cycle %1 · %2 s</translation>
    </message>
    <message>
        <source>%1.Complete = %2 (after the last call of its function block)</source>
        <translation>%1.Complete = %2 (après le dernier appel de son bloc fonctionnel)</translation>
    </message>
    <message>
        <source>No visible step is active (State = %1).</source>
        <translation>Aucune étape visible n&apos;est active (State = %1).</translation>
    </message>
    <message>
        <source>Active step: &lt;b&gt;%1&lt;/b&gt; %2 · Entry = %3</source>
        <translation>Étape active&#xa0;: &lt;b&gt;%1&lt;/b&gt; %2 · Entry = %3</translation>
    </message>
    <message>
        <source>%1 (family)</source>
        <translation>%1 (famille)</translation>
    </message>
    <message>
        <source>The active step has no transition to evaluate.</source>
        <translation>L&apos;étape active n&apos;a aucune transition à évaluer.</translation>
    </message>
    <message>
        <source>Record this session as a scenario file, or replay one.</source>
        <translation>Enregistrez cette session comme fichier de scénario, ou rejouez-en un.</translation>
    </message>
    <message>
        <source>%1: every expectation met (%2).</source>
        <translation>%1&#xa0;: toutes les attentes sont satisfaites (%2).</translation>
    </message>
    <message>
        <source>%1: %2 of %3 expectations failed.</source>
        <translation>%1&#xa0;: %2 attentes sur %3 non satisfaites.</translation>
    </message>
    <message>
        <source>Line %1: %2</source>
        <translation>Ligne %1&#xa0;: %2</translation>
    </message>
    <message>
        <source>session</source>
        <translation>session</translation>
    </message>
    <message>
        <source>Record as Scenario</source>
        <translation>Enregistrer comme scénario</translation>
    </message>
    <message>
        <source>Simulation scenarios (*.scenario *.txt);;All files (*)</source>
        <translation>Scénarios de simulation (*.scenario *.txt);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>Impossible d&apos;écrire %1.</translation>
    </message>
    <message>
        <source>Recorded %1 scans to %2.</source>
        <translation>%1 cycles enregistrés dans %2.</translation>
    </message>
    <message>
        <source>Replay Scenario</source>
        <translation>Rejouer un scénario</translation>
    </message>
    <message>
        <source>Could not replay %1.</source>
        <translation>Impossible de rejouer %1.</translation>
    </message>
    <message>
        <source>upstream step not active</source>
        <translation>étape amont non active</translation>
    </message>
    <message>
        <source>receptivity FALSE</source>
        <translation>réceptivité FALSE</translation>
    </message>
    <message>
        <source>receptivity unusable (always FALSE)</source>
        <translation>réceptivité inutilisable (toujours FALSE)</translation>
    </message>
    <message>
        <source>not called</source>
        <translation>non appelé</translation>
    </message>
    <message>
        <source>Save this session since the last reset as a scenario file: the inputs of each scan, and expectations for every transition that fired, every output that changed and every nested situation that changed</source>
        <translation>Enregistrer cette session depuis la dernière réinitialisation dans un fichier de scénario&#xa0;: les entrées de chaque cycle et des attentes pour chaque transition franchie, chaque sortie qui a changé et chaque situation d&apos;un GRAFCET imbriqué qui a changé</translation>
    </message>
    <message>
        <source>GRAFCET of %1: no step active</source>
        <translation>GRAFCET de %1 : aucune étape active</translation>
    </message>
    <message>
        <source>GRAFCET of %1: steps %2</source>
        <translation>GRAFCET de %1 : étapes %2</translation>
    </message>
    <message>
        <source>initialised again in the next scan (steps %1)</source>
        <translation>réinitialisé au prochain cycle (étapes %1)</translation>
    </message>
    <message>
        <source>first evolution of the next scan</source>
        <translation>première évolution du prochain cycle</translation>
    </message>
    <message>
        <source>Until stable: the next scan&apos;s first evolution is explained; later evolutions of the same scan follow with edges FALSE.</source>
        <translation>Jusqu&apos;à stabilité : la première évolution du prochain cycle est expliquée ; les évolutions suivantes du même cycle suivent avec les fronts à FALSE.</translation>
    </message>
    <message>
        <source>One evolution per scan.</source>
        <translation>Une évolution par cycle.</translation>
    </message>
    <message>
        <source>%1 (step %2): %3 ms of %4 ms</source>
        <extracomment>%1: a timer of a time-dependent receptivity; %2: its step; %3 of %4: elapsed and set time in ms</extracomment>
        <translation>%1 (étape %2) : %3 ms sur %4 ms</translation>
    </message>
    <message>
        <source>Outputs: %1</source>
        <extracomment>the outputs a nested GRAFCET drives, with their values (&quot;Spindle = TRUE, Marker = FALSE&quot;)</extracomment>
        <translation>Sorties : %1</translation>
    </message>
    <message>
        <source>T%1 (%2 → %3)</source>
        <extracomment>a transition of a nested GRAFCET: its number, upstream and downstream steps</extracomment>
        <translation>T%1 (%2 → %3)</translation>
    </message>
    <message>
        <source>Outputs and internal variables</source>
        <translation>Sorties et variables internes</translation>
    </message>
    <message>
        <source>Written by the program: %1 is not an input</source>
        <translation>Écrite par le programme&#xa0;: %1 n&apos;est pas une entrée</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Précédent</translation>
    </message>
    <message>
        <source>Show the previous scan of the history (%1); a scan or Run from a past scan continues from it and drops the later scans</source>
        <translation>Afficher le cycle précédent de l&apos;historique (%1)&#xa0;; un cycle ou Exécuter depuis un cycle passé repart de celui-ci et abandonne les cycles suivants</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Suivant</translation>
    </message>
    <message>
        <source>Show the next scan of the history (%1)</source>
        <translation>Afficher le cycle suivant de l&apos;historique (%1)</translation>
    </message>
    <message>
        <source>Scan %1 of %2 (history) · %3 s</source>
        <extracomment>%1 of %2: the past scan shown and the latest scan run; %3: its simulated time in seconds</extracomment>
        <translation>Cycle %1 sur %2 (historique) · %3 s</translation>
    </message>
    <message>
        <source>Replaying %1: scan %2 of %3.</source>
        <extracomment>%1: the scenario file; %2 of %3: the scan reached and the scenario&apos;s last scan</extracomment>
        <translation>Relecture de %1&#xa0;: cycle %2 sur %3.</translation>
    </message>
    <message>
        <source>Replay of %1: paused at scan %2 of %3. Press %4 to step, or Run to play the rest.</source>
        <extracomment>%1: the scenario file; %2 of %3: the scan reached and the scenario&apos;s last scan; %4: a key (F10)</extracomment>
        <translation>Relecture de %1&#xa0;: en pause au cycle %2 sur %3. Appuyez sur %4 pour avancer d&apos;un cycle, ou sur Exécuter pour jouer la suite.</translation>
    </message>
    <message>
        <source>Unstable: the GRAFCET of %1 found no stable situation in this scan; its last evolution still fired.</source>
        <extracomment>Unstable is the name of the function block&apos;s output (not translated); %1: macro-steps or enclosing steps</extracomment>
        <translation>Unstable&#xa0;: le GRAFCET de %1 n&apos;a trouvé aucune situation stable dans ce cycle&#xa0;; sa dernière évolution a encore franchi une transition.</translation>
    </message>
    <message>
        <source>the condition of %1</source>
        <translation>la réceptivité de %1</translation>
    </message>
    <message>
        <source>the receptivity of T%1 of %2</source>
        <translation>la réceptivité de T%1 de %2</translation>
    </message>
    <message>
        <source>action %1 of step %2 of %3</source>
        <translation>l&apos;action %1 de l&apos;étape %2 de %3</translation>
    </message>
    <message>
        <source>Stopped at scan %1: integer division by zero in %2 (%3 in &apos;%4&apos;). On the PLC the task stops with a fault; Reset to run again.</source>
        <translation>Arrêt au cycle %1 : division entière par zéro dans %2 (%3 dans &apos;%4&apos;). Sur l&apos;automate, la tâche s&apos;arrête sur un défaut ; Réinitialiser pour relancer.</translation>
    </message>
    <message numerus="yes">
        <source>%n other transition(s): an upstream step is not active</source>
        <extracomment>the transitions of a large nested GRAFCET left out of the explanation</extracomment>
        <translation>
            <numerusform>%n autre transition : une étape amont n&apos;est pas active</numerusform>
            <numerusform>%n autres transitions : une étape amont n&apos;est pas active</numerusform>
        </translation>
    </message>
    <message>
        <source>Sensors (set by the machine)</source>
        <translation>Capteurs (positionnés par la machine)</translation>
    </message>
    <message>
        <source>Written by the machine: %1 is a sensor of %2</source>
        <translation>Écrit par la machine : %1 est un capteur de %2</translation>
    </message>
    <message>
        <source>It sets the machine&apos;s sensors itself: played in open loop, the machine stands still.</source>
        <translation>Il positionne lui-même les capteurs de la machine : joué en boucle ouverte, la machine reste immobile.</translation>
    </message>
    <message>
        <source>Right-click to inject a fault</source>
        <translation>Clic droit pour injecter une défaillance</translation>
    </message>
</context>
<context>
    <name>editor::SimulationSession</name>
    <message>
        <source>(%1 more)</source>
        <translation>(%1 de plus)</translation>
    </message>
    <message>
        <source>%1 is a sensor of the machine&apos;s %2: the machine sets it</source>
        <translation>%1 est un capteur de %2 de la machine : c&apos;est la machine qui le positionne</translation>
    </message>
    <message>
        <source>The replay plays the machine&apos;s faults: stop it first</source>
        <translation>La relecture joue les défaillances de la machine : arrêtez-la d&apos;abord</translation>
    </message>
    <message>
        <source>A fault needs the virtual machine running in closed loop</source>
        <translation>Une défaillance a besoin de la machine virtuelle en boucle fermée</translation>
    </message>
</context>
<context>
    <name>editor::StPreviewDock</name>
    <message>
        <source>Structured Text</source>
        <translation>Texte structuré (ST)</translation>
    </message>
    <message>
        <source>&amp;Dialect:</source>
        <translation>&amp;Dialecte&#xa0;:</translation>
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
        <translation>Beremiz, OpenPLC, TwinCAT, matiec&#xa0;: variables globales dans la configuration</translation>
    </message>
    <message>
        <source>CODESYS V3.5: globals in the list GVL, read as GVL.Name</source>
        <translation>CODESYS V3.5&#xa0;: variables globales dans la liste GVL, lues sous la forme GVL.Nom</translation>
    </message>
    <message>
        <source>The flavour of the generated code; saved with the model</source>
        <translation>La variante du code généré&#xa0;; enregistrée avec le modèle</translation>
    </message>
    <message>
        <source>%1 is hidden: it generates no code.</source>
        <translation>%1 est masquée&#xa0;: elle ne génère aucun code.</translation>
    </message>
    <message>
        <source>This transition is not effective: it generates no code.</source>
        <translation>Cette transition n&apos;est pas effective&#xa0;: elle ne génère aucun code.</translation>
    </message>
    <message>
        <source>%1 generates no function block: only a visible macro-step or enclosing step does.</source>
        <translation>%1 ne génère aucun bloc fonctionnel&#xa0;: seule une macro-étape ou une étape encapsulante visible en génère un.</translation>
    </message>
    <message>
        <source>%1_FB (the nested GRAFCET of %1)</source>
        <extracomment>the function block shown: &quot;F1_FB (the nested GRAFCET of F1)&quot;</extracomment>
        <translation>%1_FB (le GRAFCET imbriqué de %1)</translation>
    </message>
    <message>
        <source>No enabled state runs this GRAFCET: it generates no function block.</source>
        <translation>Aucun état activé n&apos;exécute ce GRAFCET : il ne génère aucun bloc fonctionnel.</translation>
    </message>
    <message>
        <source>%1 is disabled in this unit mode: the mode&apos;s state machine has no branch for it.</source>
        <translation>%1 est désactivé dans ce mode d&apos;unité : la machine à états du mode n&apos;a pas de branche pour lui.</translation>
    </message>
</context>
<context>
    <name>editor::StartGuide</name>
    <message>
        <source>Getting started</source>
        <translation>Pour commencer</translation>
    </message>
    <message>
        <source>&lt;b&gt;Hide&lt;/b&gt; what your machine does not need: select states or transitions and press Delete (Shift+Delete shows them again).</source>
        <translation>&lt;b&gt;Masquez&lt;/b&gt; ce dont votre machine n’a pas besoin : sélectionnez des états ou des transitions et appuyez sur Suppr (Maj+Suppr les réaffiche).</translation>
    </message>
    <message>
        <source>&lt;b&gt;Declare&lt;/b&gt; the buttons, sensors and actuators in the Variables panel below.</source>
        <translation>&lt;b&gt;Déclarez&lt;/b&gt; les boutons, capteurs et actionneurs dans le panneau Variables ci-dessous.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Write&lt;/b&gt; each transition&apos;s condition: select the transition and press Enter. Red marks what is not finished yet.</source>
        <translation>&lt;b&gt;Écrivez&lt;/b&gt; la condition de chaque transition : sélectionnez la transition et appuyez sur Entrée. Le rouge signale ce qui n’est pas encore fini.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Simulate&lt;/b&gt; with F5, &lt;b&gt;verify&lt;/b&gt; with F7, then export PLCopen XML for your PLC.</source>
        <translation>&lt;b&gt;Simulez&lt;/b&gt; avec F5, &lt;b&gt;vérifiez&lt;/b&gt; avec F7, puis exportez le PLCopen XML pour votre automate.</translation>
    </message>
    <message>
        <source>The chart is the GEMMA sheet: the ways your machine stops (A), works (F) and fails (D), and the transitions between them.</source>
        <translation>Le diagramme est la feuille GEMMA : comment votre machine s’arrête (A), fonctionne (F) et défaille (D), et les transitions entre ces états.</translation>
    </message>
    <message>
        <source>Select a step or a transition to edit it here.</source>
        <translation>Sélectionnez une étape ou une transition pour la modifier ici.</translation>
    </message>
    <message>
        <source>Open an Example</source>
        <translation>Ouvrir un exemple</translation>
    </message>
    <message>
        <source>A finished model to look at and simulate, opened as an untitled copy</source>
        <translation>Un modèle terminé à regarder et à simuler, ouvert comme copie sans titre</translation>
    </message>
    <message>
        <source>User Guide</source>
        <translation>Guide de l’utilisateur</translation>
    </message>
    <message>
        <source>How to build a model step by step (F1)</source>
        <translation>Comment construire un modèle pas à pas (F1)</translation>
    </message>
</context>
<context>
    <name>editor::StepDock</name>
    <message>
        <source>Step</source>
        <translation>Étape</translation>
    </message>
    <message>
        <source>Select a step in the chart to see and edit its properties.</source>
        <translation>Sélectionnez une étape dans le diagramme pour voir et modifier ses propriétés.</translation>
    </message>
    <message>
        <source>Simple step: no nested behaviour.
Macro-step: its transitions wait until the nested behaviour is complete.
Enclosing step: its transitions fire whatever the nested behaviour is doing.</source>
        <translation>Étape simple&#xa0;: aucun comportement imbriqué.
Macro-étape&#xa0;: ses transitions attendent que le comportement imbriqué soit terminé.
Étape encapsulante&#xa0;: ses transitions sont franchies quel que soit l&apos;état du comportement imbriqué.</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Type&#xa0;:</translation>
    </message>
    <message>
        <source>&amp;Initial</source>
        <translation>&amp;Initiale</translation>
    </message>
    <message>
        <source>&amp;Hidden</source>
        <translation>&amp;Masquée</translation>
    </message>
    <message>
        <source>A hidden step is not part of this machine: it generates no code, and its transitions are not effective.</source>
        <translation>Une étape masquée ne fait pas partie de cette machine&#xa0;: elle ne génère aucun code et ses transitions ne sont pas effectives.</translation>
    </message>
    <message>
        <source>What this state does on this machine</source>
        <translation>Ce que fait cet état sur cette machine</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Commentaire&#xa0;:</translation>
    </message>
    <message>
        <source>Incoming transitions</source>
        <translation>Transitions d&apos;entrée</translation>
    </message>
    <message>
        <source>Outgoing transitions, by priority</source>
        <translation>Transitions de sortie, par priorité</translation>
    </message>
    <message>
        <source>Transition</source>
        <translation>Transition</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Réceptivité</translation>
    </message>
    <message>
        <source>Click a transition to select it</source>
        <translation>Cliquez sur une transition pour la sélectionner</translation>
    </message>
    <message>
        <source>%1 · state number %2</source>
        <translation>%1 · état numéro %2</translation>
    </message>
    <message>
        <source>%1 is the initial step. There is always exactly one initial step: to change it, make another step initial.</source>
        <translation>%1 est l&apos;étape initiale. Il y a toujours exactement une étape initiale&#xa0;: pour la changer, rendez une autre étape initiale.</translation>
    </message>
    <message>
        <source>Make %1 the initial step (the PLC starts in it). The current initial step is %2.</source>
        <translation>Faire de %1 l&apos;étape initiale (l&apos;automate démarre dans celle-ci). L&apos;étape initiale actuelle est %2.</translation>
    </message>
    <message>
        <source>F (family) →</source>
        <extracomment>an incoming transition: its source, an arrow</extracomment>
        <translation>F (famille) →</translation>
    </message>
    <message>
        <source>%1 →</source>
        <translation>%1 →</translation>
    </message>
    <message>
        <source>F: → %1</source>
        <extracomment>the family transition in the outgoing list of an F state</extracomment>
        <translation>F&#xa0;: → %1</translation>
    </message>
    <message>
        <source>%1: → %2</source>
        <extracomment>an outgoing transition: priority, arrow, target (&quot;1: → F4&quot;); – when it has none</extracomment>
        <translation>%1&#xa0;: → %2</translation>
    </message>
    <message>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <source>Family transition: evaluated before the own transitions of every visible F state.</source>
        <translation>Transition de famille&#xa0;: évaluée avant les transitions propres de chaque état F visible.</translation>
    </message>
    <message>
        <source>Negated</source>
        <translation>Niée</translation>
    </message>
    <message>
        <source>Condition: %1</source>
        <translation>Réceptivité&#xa0;: %1</translation>
    </message>
    <message>
        <source>Not effective (%1): generates no code.</source>
        <translation>Non effective (%1)&#xa0;: ne génère aucun code.</translation>
    </message>
    <message>
        <source>%1 (negated)</source>
        <extracomment>a negated transition in the Step dock&apos;s lists: the entry, then the mark</extracomment>
        <translation>%1 (niée)</translation>
    </message>
    <message>
        <source>Open Nested GRAFCET</source>
        <translation>Ouvrir le GRAFCET imbriqué</translation>
    </message>
    <message>
        <source>Show the nested GRAFCET of this step in a tab beside the GEMMA chart (double-click the step on the chart does the same)</source>
        <translation>Afficher le GRAFCET imbriqué de cette étape dans un onglet à côté du diagramme GEMMA (un double-clic sur l’étape du diagramme fait de même)</translation>
    </message>
</context>
<context>
    <name>editor::StepItem</name>
    <message>
        <source>Simple step</source>
        <translation>Étape simple</translation>
    </message>
    <message>
        <source>Macro-step</source>
        <translation>Macro-étape</translation>
    </message>
    <message>
        <source>Enclosing step</source>
        <translation>Étape encapsulante</translation>
    </message>
    <message>
        <source>%1, initial</source>
        <translation>%1, initiale</translation>
    </message>
    <message>
        <source>%1, hidden</source>
        <translation>%1, masquée</translation>
    </message>
    <message numerus="yes">
        <source>Has a nested GRAFCET (%n steps)</source>
        <translation>
            <numerusform>A un GRAFCET imbriqué (%n étape)</numerusform>
            <numerusform>A un GRAFCET imbriqué (%n étapes)</numerusform>
        </translation>
    </message>
    <message>
        <source>Its GRAFCET runs: steps %1 active</source>
        <extracomment>simulation; %1: the active steps of the nested GRAFCET (&quot;3, 5&quot;)</extracomment>
        <translation>Son GRAFCET évolue&#xa0;: étapes %1 actives</translation>
    </message>
    <message>
        <source>Its nested GRAFCET has 1 problem</source>
        <translation>Son GRAFCET imbriqué a 1 problème</translation>
    </message>
    <message numerus="yes">
        <source>Its nested GRAFCET has %n problems</source>
        <translation>
            <numerusform>Son GRAFCET imbriqué a %n problème</numerusform>
            <numerusform>Son GRAFCET imbriqué a %n problèmes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>editor::TraceTableModel</name>
    <message>
        <source>Scan</source>
        <translation>Cycle</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Étape</translation>
    </message>
    <message>
        <source>Fired</source>
        <translation>Franchie</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Entry</translation>
    </message>
    <message>
        <source>Tokens TRUE</source>
        <translation>Mémoires TRUE</translation>
    </message>
    <message>
        <source>Changed inputs</source>
        <translation>Entrées modifiées</translation>
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
        <translation>Sélectionnez une transition dans le diagramme pour voir et modifier sa réceptivité.</translation>
    </message>
    <message>
        <source>Click a step to select it</source>
        <translation>Cliquez sur une étape pour la sélectionner</translation>
    </message>
    <message>
        <source>C&amp;ondition:</source>
        <translation>&amp;Réceptivité&#xa0;:</translation>
    </message>
    <message>
        <source>e.g. Start AND NOT Stop</source>
        <translation>ex. Start AND NOT Stop</translation>
    </message>
    <message>
        <source>Structured Text: declared variables, numbers, TRUE, FALSE, NOT, AND (&amp;), XOR, OR, comparisons and arithmetic.
Ctrl+Space completes a variable name.</source>
        <translation>Texte structuré (ST)&#xa0;: variables déclarées, nombres, TRUE, FALSE, NOT, AND (&amp;), XOR, OR, comparaisons et arithmétique.
Ctrl+Espace complète un nom de variable.</translation>
    </message>
    <message>
        <source>&amp;Priority:</source>
        <translation>&amp;Priorité&#xa0;:</translation>
    </message>
    <message>
        <source>&amp;Negated</source>
        <translation>&amp;Niée</translation>
    </message>
    <message>
        <source>Negation flips when this transition waits for the nested behaviour of its source:
a negated transition out of a macro-step ignores Complete;
a negated transition out of an enclosing step waits for Complete.</source>
        <translation>La négation inverse l&apos;attente de cette transition sur le comportement imbriqué de sa source&#xa0;:
une transition niée issue d&apos;une macro-étape ignore Complete&#xa0;;
une transition niée issue d&apos;une étape encapsulante attend Complete.</translation>
    </message>
    <message>
        <source>&amp;Hidden</source>
        <translation>&amp;Masquée</translation>
    </message>
    <message>
        <source>A hidden transition is not part of this machine: it generates no code.</source>
        <translation>Une transition masquée ne fait pas partie de cette machine&#xa0;: elle ne génère aucun code.</translation>
    </message>
    <message>
        <source>Tokens</source>
        <translation>Mémoires</translation>
    </message>
    <message>
        <source>F (family)</source>
        <translation>F (famille)</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <extracomment>a transition: source step, arrow, target step</extracomment>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Not effective (%1): generates no code.</source>
        <translation>Non effective (%1)&#xa0;: ne génère aucun code.</translation>
    </message>
    <message>
        <source>First</source>
        <translation>Première</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Aucune</translation>
    </message>
    <message>
        <source>The family transition is evaluated before the own transitions of every visible F state.</source>
        <translation>La transition de famille est évaluée avant les transitions propres de chaque état F visible.</translation>
    </message>
    <message>
        <source>Only effective transitions have a priority: show this transition and both its steps first.</source>
        <translation>Seules les transitions effectives ont une priorité&#xa0;: affichez d&apos;abord cette transition et ses deux étapes.</translation>
    </message>
    <message>
        <source> of %1</source>
        <extracomment>after the priority in its spin box: &quot;2 of 5&quot;</extracomment>
        <translation> sur %1</translation>
    </message>
    <message>
        <source>1 is evaluated first among the effective transitions out of %1; the others move to make room.</source>
        <translation>1 est évaluée en premier parmi les transitions effectives issues de %1&#xa0;; les autres se décalent pour faire de la place.</translation>
    </message>
    <message>
        <source>Negation has no effect here: family transitions never wait for Complete.</source>
        <translation>La négation n&apos;a aucun effet ici&#xa0;: les transitions de famille n&apos;attendent jamais Complete.</translation>
    </message>
    <message>
        <source>Negation has no effect here: %1 is a simple step, and only transitions out of macro-steps and enclosing steps wait for Complete.</source>
        <translation>La négation n&apos;a aucun effet ici&#xa0;: %1 est une étape simple, et seules les transitions issues de macro-étapes et d&apos;étapes encapsulantes attendent Complete.</translation>
    </message>
    <message>
        <source>Fires without waiting for the nested behaviour of macro-step %1 to complete.</source>
        <translation>Franchie sans attendre que le comportement imbriqué de la macro-étape %1 soit terminé.</translation>
    </message>
    <message>
        <source>Waits until the nested behaviour of macro-step %1 is complete (%1.Complete). Negate it to fire at once.</source>
        <translation>Attend que le comportement imbriqué de la macro-étape %1 soit terminé (%1.Complete). Niez-la pour la franchir immédiatement.</translation>
    </message>
    <message>
        <source>Waits until the nested behaviour of enclosing step %1 is complete (%1.Complete).</source>
        <translation>Attend que le comportement imbriqué de l&apos;étape encapsulante %1 soit terminé (%1.Complete).</translation>
    </message>
    <message>
        <source>Fires whatever the nested behaviour of enclosing step %1 is doing. Negate it to wait for %1.Complete.</source>
        <translation>Franchie quel que soit l&apos;état du comportement imbriqué de l&apos;étape encapsulante %1. Niez-la pour attendre %1.Complete.</translation>
    </message>
    <message>
        <source>Token on %1 (compared: no polarity)</source>
        <translation>Mémoire de %1 (comparée&#xa0;: sans polarité)</translation>
    </message>
    <message>
        <source>Token on %1 (both NO and NC)</source>
        <translation>Mémoire de %1 (à la fois NO et NF)</translation>
    </message>
    <message>
        <source>Token on %1 (NC)</source>
        <translation>Mémoire de %1 (NF)</translation>
    </message>
    <message>
        <source>Token on %1 (NO)</source>
        <translation>Mémoire de %1 (NO)</translation>
    </message>
    <message>
        <source>A token replaces a literal %1 or NOT %1: rewrite the condition so that %1 has one polarity.</source>
        <translation>Une mémoire remplace un littéral %1 ou NOT %1&#xa0;: réécrivez la réceptivité pour que %1 n&apos;ait qu&apos;une polarité.</translation>
    </message>
    <message>
        <source>Normally closed: remembers that %1 was FALSE while the nested behaviour of %2 was not complete.</source>
        <translation>Normalement fermée&#xa0;: retient que %1 a été FALSE pendant que le comportement imbriqué de %2 n&apos;était pas terminé.</translation>
    </message>
    <message>
        <source>Normally open: remembers that %1 was TRUE while the nested behaviour of %2 was not complete.</source>
        <translation>Normalement ouverte&#xa0;: retient que %1 a été TRUE pendant que le comportement imbriqué de %2 n&apos;était pas terminé.</translation>
    </message>
    <message>
        <source>Generated as %1_%2_%3_MEM.</source>
        <translation>Générée sous le nom %1_%2_%3_MEM.</translation>
    </message>
    <message>
        <source>Token on %1 (not a BOOL variable of the condition)</source>
        <translation>Mémoire de %1 (pas une variable BOOL de la réceptivité)</translation>
    </message>
    <message>
        <source>Uncheck to remove this token.</source>
        <translation>Décochez pour supprimer cette mémoire.</translation>
    </message>
    <message>
        <source>Family transitions never wait for Complete, so tokens do not apply to them.</source>
        <translation>Les transitions de famille n&apos;attendent jamais Complete&#xa0;: les mémoires ne s&apos;y appliquent donc pas.</translation>
    </message>
    <message>
        <source>Tokens apply to transitions out of macro-steps and enclosing steps; %1 is a simple step.</source>
        <translation>Les mémoires s&apos;appliquent aux transitions issues de macro-étapes et d&apos;étapes encapsulantes&#xa0;; %1 est une étape simple.</translation>
    </message>
    <message>
        <source>Correct the condition to choose its tokens.</source>
        <translation>Corrigez la réceptivité pour choisir ses mémoires.</translation>
    </message>
    <message>
        <source>The condition uses no BOOL variable.</source>
        <translation>La réceptivité n&apos;utilise aucune variable BOOL.</translation>
    </message>
    <message>
        <source>A token keeps a short pulse of a BOOL variable that occurs while the nested behaviour of %1 is not yet complete.</source>
        <translation>Une mémoire retient une impulsion brève d&apos;une variable BOOL survenue pendant que le comportement imbriqué de %1 n&apos;est pas encore terminé.</translation>
    </message>
</context>
<context>
    <name>editor::TransitionItem</name>
    <message>
        <source>Family transition: applies to every F state</source>
        <translation>Transition de famille&#xa0;: s&apos;applique à chaque état F</translation>
    </message>
    <message>
        <source>Priority %1</source>
        <translation>Priorité %1</translation>
    </message>
    <message>
        <source>Not effective (hidden)</source>
        <translation>Non effective (masquée)</translation>
    </message>
    <message>
        <source>%1, negated</source>
        <translation>%1, niée</translation>
    </message>
    <message>
        <source>Condition:</source>
        <translation>Réceptivité&#xa0;:</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>vide</translation>
    </message>
    <message>
        <source>Tokens: %1</source>
        <translation>Mémoires&#xa0;: %1</translation>
    </message>
</context>
<context>
    <name>editor::UserGuide</name>
    <message>
        <source>GG Studio User Guide</source>
        <translation>Guide de l&apos;utilisateur de GG Studio</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Précédent</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Suivant</translation>
    </message>
    <message>
        <source>Getting Started</source>
        <translation>Premiers pas</translation>
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
        <translation>Filtrer</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Ajouter</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Dupliquer</translation>
    </message>
    <message>
        <source>Duplicate the selected variables</source>
        <translation>Dupliquer les variables sélectionnées</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Monter</translation>
    </message>
    <message>
        <source>Move the current variable up (declaration order)</source>
        <translation>Monter la variable courante (ordre de déclaration)</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Descendre</translation>
    </message>
    <message>
        <source>Move the current variable down (declaration order)</source>
        <translation>Descendre la variable courante (ordre de déclaration)</translation>
    </message>
    <message>
        <source>Sort by Name</source>
        <translation>Trier par nom</translation>
    </message>
    <message>
        <source>Sort the declarations by name (one undo step)</source>
        <translation>Trier les déclarations par nom (une seule étape d&apos;annulation)</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Copier</translation>
    </message>
    <message>
        <source>Paste</source>
        <translation>Coller</translation>
    </message>
    <message>
        <source>Variable%1</source>
        <translation>Variable%1</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n variables</source>
        <translation>
            <numerusform>Supprimer %n variable</numerusform>
            <numerusform>Supprimer %n variables</numerusform>
        </translation>
    </message>
    <message>
        <source>Sort variables by name</source>
        <translation>Trier les variables par nom</translation>
    </message>
    <message>
        <source>Remove the selected variables</source>
        <translation>Supprimer les variables sélectionnées</translation>
    </message>
    <message>
        <source>Copy the selected variables as tab-separated rows</source>
        <translation>Copier les variables sélectionnées en lignes séparées par des tabulations</translation>
    </message>
    <message>
        <source>Show only the variables whose name, type, kind, default or comment contains this text</source>
        <translation>N&apos;afficher que les variables dont le nom, le type, la nature, la valeur initiale ou le commentaire contient ce texte</translation>
    </message>
    <message>
        <source>Add a BOOL variable after the current one (Insert)</source>
        <translation>Ajouter une variable BOOL après la variable courante (Inser)</translation>
    </message>
    <message>
        <source>Paste rows from a spreadsheet: name, type, default, comment and kind, in this order or in the order a first row of column titles gives</source>
        <translation>Coller des lignes d&apos;un tableur : nom, type, valeur initiale, commentaire et nature, dans cet ordre ou dans l&apos;ordre que donne une première ligne de titres de colonnes</translation>
    </message>
</context>
<context>
    <name>editor::VariablesTableModel</name>
    <message>
        <source>No default: the PLC starts with %1.</source>
        <translation>Pas de valeur initiale&#xa0;: l&apos;automate démarre avec %1.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a supported type: use one of %2.</source>
        <translation>&apos;%1&apos; n&apos;est pas un type pris en charge&#xa0;: utilisez l&apos;un de ceux-ci&#xa0;: %2.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Valeur initiale</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Commentaire</translation>
    </message>
    <message>
        <source>IEC 61131-3 identifier, unique ignoring case. Renaming updates every condition.</source>
        <translation>Identificateur IEC 61131-3, unique sans tenir compte de la casse. Le renommage met à jour toutes les réceptivités.</translation>
    </message>
    <message>
        <source>Elementary IEC 61131-3 type</source>
        <translation>Type élémentaire IEC 61131-3</translation>
    </message>
    <message>
        <source>Initial value, a literal of the type; empty for the type&apos;s implicit default</source>
        <translation>Valeur initiale, un littéral du type&#xa0;; vide pour la valeur par défaut implicite du type</translation>
    </message>
    <message>
        <source>Free text, written into the generated declarations</source>
        <translation>Texte libre, écrit dans les déclarations générées</translation>
    </message>
    <message>
        <source>Line %1: the name is empty.</source>
        <translation>Ligne %1&#xa0;: le nom est vide.</translation>
    </message>
    <message>
        <source>Line %1: &apos;%2&apos; is not a supported type: use one of %3.</source>
        <translation>Ligne %1&#xa0;: &apos;%2&apos; n&apos;est pas un type pris en charge&#xa0;: utilisez l&apos;un de ceux-ci&#xa0;: %3.</translation>
    </message>
    <message>
        <source>There are no variables to paste: copy rows of name, type, default and comment, separated by tabs.</source>
        <translation>Il n&apos;y a aucune variable à coller&#xa0;: copiez des lignes de nom, type, valeur initiale et commentaire, séparés par des tabulations.</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Sortie</translation>
    </message>
    <message>
        <source>Internal</source>
        <translation>Interne</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Entrée</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a kind: use %2, %3 or %4.</source>
        <translation>&apos;%1&apos; n&apos;est pas une nature&#xa0;: utilisez %2, %3 ou %4.</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Nature</translation>
    </message>
    <message>
        <source>Input: read from the machine. Output: written by the actions of nested GRAFCETs. Internal: a memory the program writes and reads.</source>
        <translation>Entrée&#xa0;: lue sur la machine. Sortie&#xa0;: écrite par les actions des GRAFCET imbriqués. Interne&#xa0;: une mémoire que le programme écrit et lit.</translation>
    </message>
    <message>
        <source>Line %1: &apos;%2&apos; is not a kind: use input, output or internal.</source>
        <translation>Ligne %1&#xa0;: &apos;%2&apos; n&apos;est pas une nature&#xa0;: utilisez entrée, sortie ou interne.</translation>
    </message>
</context>
<context>
    <name>editor::VerificationPanel</name>
    <message>
        <source>&amp;Verify</source>
        <translation>&amp;Vérifier</translation>
    </message>
    <message>
        <source>&amp;Show on Chart</source>
        <translation>&amp;Montrer sur le diagramme</translation>
    </message>
    <message>
        <source>&amp;Replay in Simulator</source>
        <translation>&amp;Rejouer dans le simulateur</translation>
    </message>
    <message>
        <source>Explore every input sequence of the GEMMA layer and report what cannot happen</source>
        <translation>Explorer toutes les séquences d&apos;entrées de la couche GEMMA et signaler ce qui ne peut pas arriver</translation>
    </message>
    <message>
        <source>Select the element of the finding on the chart</source>
        <translation>Sélectionner l&apos;élément du résultat sur le diagramme</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <source>Element</source>
        <translation>Élément</translation>
    </message>
    <message>
        <source>Scans</source>
        <translation>Cycles</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <source>Scans of the counterexample, which the simulator can replay</source>
        <translation>Cycles du contre-exemple, que le simulateur peut rejouer</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copier</translation>
    </message>
    <message>
        <source>Verifying…</source>
        <translation>Vérification…</translation>
    </message>
    <message>
        <source>Verification failed: %1.</source>
        <translation>Échec de la vérification&#xa0;: %1.</translation>
    </message>
    <message>
        <source>Not verified yet.</source>
        <translation>Pas encore vérifié.</translation>
    </message>
    <message>
        <source>Model changed since verification: verify again to update the findings.</source>
        <translation>Le modèle a changé depuis la vérification&#xa0;: vérifiez à nouveau pour mettre à jour les résultats.</translation>
    </message>
    <message>
        <source>Some properties do not hold (%1 configurations explored).</source>
        <translation>Certaines propriétés ne sont pas satisfaites (%1 configurations explorées).</translation>
    </message>
    <message>
        <source>Every property holds; see the notes (%1 configurations explored).</source>
        <translation>Toutes les propriétés sont satisfaites&#xa0;; voir les remarques (%1 configurations explorées).</translation>
    </message>
    <message>
        <source>Every property holds (%1 configurations explored).</source>
        <translation>Toutes les propriétés sont satisfaites (%1 configurations explorées).</translation>
    </message>
    <message>
        <source>The model changed since verification: verify again to replay</source>
        <translation>Le modèle a changé depuis la vérification&#xa0;: vérifiez à nouveau pour rejouer</translation>
    </message>
    <message>
        <source>Start the simulation and replay the scans that lead to the finding</source>
        <translation>Démarrer la simulation et rejouer les cycles qui mènent au résultat</translation>
    </message>
    <message>
        <source>Complete settings changed since verification: verify again to update the findings.</source>
        <translation>Les réglages de Complete ont changé depuis la vérification&#xa0;: vérifiez à nouveau pour mettre à jour les résultats.</translation>
    </message>
    <message>
        <source>All Complete outputs free</source>
        <translation>Toutes les sorties Complete libres</translation>
    </message>
    <message>
        <source>Assumed Complete automatic: %1</source>
        <translation>Complete supposé automatique&#xa0;: %1</translation>
    </message>
    <message>
        <source>Free: the nested behaviour may complete at any scan, or never. Automatic: Complete is TRUE at every scan, as the skeleton function block. Verify assumes automatic the nested steps whose Complete is Automatic in the Simulation dock while the simulation runs; all others are free.</source>
        <translation>Libre&#xa0;: le comportement imbriqué peut se terminer à n’importe quel cycle, ou jamais. Automatique&#xa0;: Complete vaut TRUE à chaque cycle, comme dans le bloc fonctionnel squelette. La vérification suppose automatiques les étapes à comportement imbriqué dont le Complete est Automatique dans le panneau Simulation pendant la simulation&#xa0;; toutes les autres sont libres.</translation>
    </message>
    <message>
        <source>%1: T%2</source>
        <translation>%1&#xa0;: T%2</translation>
    </message>
    <message>
        <source>%1: step %2</source>
        <extracomment>A step of a nested GRAFCET: %1 the GEMMA step, %2 its number</extracomment>
        <translation>%1&#xa0;: étape %2</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modèle</translation>
    </message>
    <message>
        <source>%1: nested GRAFCET</source>
        <extracomment>The row that groups the findings about the nested GRAFCET of a GEMMA step, e.g. &quot;F1 Normal production&quot;</extracomment>
        <translation>%1&#xa0;: GRAFCET imbriqué</translation>
    </message>
    <message>
        <source>The findings about the nested GRAFCET of %1</source>
        <translation>Les constats sur le GRAFCET imbriqué de %1</translation>
    </message>
    <message>
        <source>Some properties do not hold (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Certaines propriétés ne sont pas vérifiées (%1 configurations du niveau GEMMA et %2 états du programme des deux niveaux explorés).</translation>
    </message>
    <message>
        <source>Every property holds; see the notes (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Toutes les propriétés sont vérifiées&#xa0;; voir les notes (%1 configurations du niveau GEMMA et %2 états du programme des deux niveaux explorés).</translation>
    </message>
    <message>
        <source>Every property holds (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Toutes les propriétés sont vérifiées (%1 configurations du niveau GEMMA et %2 états du programme des deux niveaux explorés).</translation>
    </message>
    <message>
        <source>The exploration of both layers abstracted:</source>
        <translation>L&apos;exploration des deux niveaux a abstrait&#xa0;:</translation>
    </message>
    <message>
        <source>Exact time switched on since verification: verify again to update the findings.</source>
        <translation>Temps exact activé depuis la vérification&#xa0;: vérifiez à nouveau pour mettre à jour les résultats.</translation>
    </message>
    <message>
        <source>Exact time switched off since verification: verify again to update the findings.</source>
        <translation>Temps exact désactivé depuis la vérification&#xa0;: vérifiez à nouveau pour mettre à jour les résultats.</translation>
    </message>
    <message>
        <source>Exact time</source>
        <translation>Temps exact</translation>
    </message>
    <message>
        <source>Exact time: every timer elapses exactly when the PLC&apos;s would, counted in scans (Simulation &gt; Verify with Exact Time).</source>
        <translation>Temps exact&#xa0;: chaque temporisation s&apos;écoule exactement quand celle de l&apos;automate le ferait, comptée en cycles (Simulation &gt; Vérifier avec le temps exact).</translation>
    </message>
    <message>
        <source>Nothing is violated, but some properties are undecided: see the findings (%1 configurations explored).</source>
        <translation>Rien n&apos;est violé, mais certaines propriétés sont indécises : voir les résultats (%1 configurations explorées).</translation>
    </message>
    <message>
        <source>Nothing is violated, but some properties are undecided: see the findings (%1 configurations of the GEMMA layer and %2 program states of both layers explored).</source>
        <translation>Rien n&apos;est violé, mais certaines propriétés sont indécises : voir les résultats (%1 configurations du niveau GEMMA et %2 états du programme des deux niveaux explorés).</translation>
    </message>
    <message>
        <source>&amp;Time limit:</source>
        <translation>&amp;Limite de temps :</translation>
    </message>
    <message>
        <source> s</source>
        <extracomment>The unit after the verification&apos;s time limit: &quot;4 s&quot;</extracomment>
        <translation> s</translation>
    </message>
    <message>
        <source>How long a verification may run. Past it, what is not decided yet is reported as undecided (GV100) with how far the exploration got: give more time and verify again.</source>
        <translation>Durée maximale d&apos;une vérification. Au-delà, ce qui n&apos;est pas encore décidé est signalé comme indécis (GV100), avec l&apos;avancement de l&apos;exploration : donnez plus de temps et vérifiez à nouveau.</translation>
    </message>
    <message>
        <source>The machine is used since verification: verify again to update the findings.</source>
        <translation>La machine est utilisée depuis la vérification : vérifiez à nouveau pour mettre à jour les constats.</translation>
    </message>
    <message>
        <source>The machine is no longer used since verification: verify again to update the findings.</source>
        <translation>La machine n&apos;est plus utilisée depuis la vérification : vérifiez à nouveau pour mettre à jour les constats.</translation>
    </message>
    <message>
        <source>With the machine</source>
        <translation>Avec la machine</translation>
    </message>
    <message>
        <source>With the machine: the sensors the model&apos;s machine drives follow it, scan by scan, instead of taking any value (Simulation &gt; Verify with the Machine).</source>
        <translation>Avec la machine : les capteurs que pilote la machine du modèle la suivent, cycle après cycle, au lieu de prendre n&apos;importe quelle valeur (Simulation &gt; Vérifier avec la machine).</translation>
    </message>
    <message>
        <source>Single faults switched on since verification: verify again to update the findings.</source>
        <translation>Défauts uniques activés depuis la vérification : vérifiez à nouveau pour mettre à jour les constats.</translation>
    </message>
    <message>
        <source>Single faults switched off since verification: verify again to update the findings.</source>
        <translation>Défauts uniques désactivés depuis la vérification : vérifiez à nouveau pour mettre à jour les constats.</translation>
    </message>
    <message>
        <source>Single faults</source>
        <translation>Défauts uniques</translation>
    </message>
    <message>
        <source>Single faults: any one sensor stuck or flickering, or one cylinder or conveyor jammed, from any scan on (Simulation &gt; Verify with Single Faults).</source>
        <translation>Défauts uniques : un capteur quelconque bloqué ou instable, ou un vérin ou un convoyeur coincé, à partir de n&apos;importe quel cycle (Simulation &gt; Vérifier avec des défauts uniques).</translation>
    </message>
</context>
<context>
    <name>editor::ZoomIndicator</name>
    <message>
        <source>Zoom: %1 %</source>
        <translation>Zoom&#xa0;: %1 %</translation>
    </message>
    <message>
        <source>The zoom of the tab in front. Ctrl+wheel or a pinch zooms about the mouse; Ctrl+0 fits the drawing in the window, Ctrl+1 shows it at its actual size</source>
        <translation>Le zoom de l’onglet au premier plan. Ctrl+molette ou un pincement zoome autour de la souris ; Ctrl+0 ajuste le dessin à la fenêtre, Ctrl+1 l’affiche à sa taille réelle</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Editor for the GEMMA-GRAFCET method of specifying machine operating modes</source>
        <translation>Éditeur pour la méthode GEMMA-GRAFCET de spécification des modes de marche et d&apos;arrêt des machines</translation>
    </message>
    <message>
        <source>The model file to open (GG Studio JSON, GG-Generator JSON or GG Studio PLCopen XML).</source>
        <translation>Le fichier de modèle à ouvrir (JSON GG Studio, JSON GG-Generator ou PLCopen XML GG Studio).</translation>
    </message>
</context>
<context>
    <name>modbus::ModbusLink</name>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation>impossible d&apos;écouter sur %1:%2 : %3</translation>
    </message>
    <message>
        <source>cannot connect to %1:%2: %3</source>
        <translation>impossible de se connecter à %1:%2 : %3</translation>
    </message>
    <message>
        <source>write of %1 %2..%3 to %4:%5</source>
        <translation>écriture de %1 %2..%3 vers %4:%5</translation>
    </message>
    <message>
        <source>read of %1 %2..%3 from %4:%5</source>
        <translation>lecture de %1 %2..%3 depuis %4:%5</translation>
    </message>
</context>
</TS>
