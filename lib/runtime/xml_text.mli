(** XML 1.0 text as rapid-sem writes it (the JUnit reports of spec --impl and test, the Cobertura
    report of test --cobertura): valid UTF-8 whatever bytes it is given, as {!Json_text} makes
    JSON. *)

val escape : string -> string
(** The text of an attribute or an element (XML 1.0 §2.2): the bytes made UTF-8 as
    {!Utf8_text.of_bytes} does, the markup characters as entities, tab, newline and carriage
    return as character references (which an attribute would otherwise turn into spaces), the
    other characters XML forbids (C0 controls, U+FFFE, U+FFFF) as [\HH] or U+FFFD. *)
