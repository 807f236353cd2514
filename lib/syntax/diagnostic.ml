type error_class =
  | Lexical_error | Syntax_error | Semantic_error | Fatal_static_error | File_error
type t = { error_class : error_class; region : Source.region; message : string }

let make error_class region message = { error_class; region; message }

let class_name = function
  | Lexical_error -> "lexical error"
  | Syntax_error -> "syntax error"
  | Semantic_error -> "semantic error"
  | Fatal_static_error -> "fatal error"
  | File_error -> "file error"

let to_string d =
  Printf.sprintf "%s: %s: %s" (Source.to_string d.region) (class_name d.error_class) d.message
