open Rapid_syntax

type data_kind =
  | Variable
  | Persistent
  | Constant
  | Parameter of Tables.access_mode
  | Loop_variable
  | Read_only_variable

type level = Routine_level | Module_level of string | Installed_level

type data_object = {
  d_name : string;
  d_type : Types.object_type;
  d_kind : data_kind;
  d_region : Source.region;
  d_level : level;
  d_scope : Ast.declaration_scope;
  d_optional : bool;
  d_initial : Ast.expression option;
}

type parameter = {
  p_name : string;
  p_mode : Tables.access_mode;
  p_type : Types.object_type option;
  p_region : Source.region;
}

type parameter_slot =
  | Required_slot of parameter
  | Optional_slot of parameter list
  | Required_choice of parameter list
type routine_kind = Procedure | Function of Types.object_type | Trap

type routine = {
  r_name : string;
  r_kind : routine_kind;
  r_slots : parameter_slot list;
  r_region : Source.region;
  r_level : level;
  r_local : bool;
  r_open : bool;
}

type type_object = {
  t_name : string;
  t_type : Types.data_type;
  t_alias : bool;
  t_region : Source.region;
  t_level : level;
  t_local : bool;
}

type obj =
  | Data of data_object
  | Routine of routine
  | Type of type_object
  | Label of Source.region
  | Module of Source.region

let obj_region = function
  | Data d -> d.d_region
  | Routine r -> r.r_region
  | Type t -> t.t_region
  | Label r -> r
  | Module r -> r

let obj_kind_name = function
  | Data _ -> "data object"
  | Routine _ -> "routine"
  | Type _ -> "data type"
  | Label _ -> "label"
  | Module _ -> "module"

type table = (string, obj) Hashtbl.t

(* Speed (bench/README.md): most names are looked up many times and many are in lower case
   already; such a name is its own key, without a copy. *)
let rec has_upper name i =
  i < String.length name
  && (match String.unsafe_get name i with 'A' .. 'Z' -> true | _ -> has_upper name (i + 1))

let key name = if has_upper name 0 then String.lowercase_ascii name else name
let create_table () = Hashtbl.create 64
let find t name = Hashtbl.find_opt t (key name)
(* Every change to a table is counted: a look-up kept (below) holds only while none was made. *)
let generation = ref 0
let add t name o = incr generation; Hashtbl.replace t (key name) o
let copy_table t = Hashtbl.copy t
let iter f t = Hashtbl.iter f t

type scope = {
  installed : table;
  globals : table;
  module_objects : table;
  module_names : table;
  routine : table list;
  in_installed_module : bool;
}

let lookup_tables scope name =
  (* the key made once for every table probed *)
  let name = key name in
  let find t name = Hashtbl.find_opt t name in
  let rec in_routine = function
    | [] -> None
    | t :: rest -> (match find t name with Some o -> Some o | None -> in_routine rest)
  in
  match in_routine scope.routine with
  | Some o -> Some o
  | None -> (
      match find scope.module_objects name with
      | Some o -> Some o
      | None -> (
          match (if scope.in_installed_module then None else find scope.globals name) with
          | Some o -> Some o
          | None -> (
              (* §9.2: a module name hides a predefined object of the same name. *)
              match (if scope.in_installed_module then None else find scope.module_names name) with
              | Some o -> Some o
              | None -> find scope.installed name)))

(* The checker asks for the same names in the same scope again and again (a call's routine and
   arguments, at each of its steps; the parser gives one string per spelling): the answers
   are kept by scope and name, both physically, while no table changed. *)
let memo_slots = 64
let no_scope = { installed = create_table (); globals = create_table (); module_objects = create_table ();
                 module_names = create_table (); routine = []; in_installed_module = false }
let memo_scopes = Array.make memo_slots no_scope
let memo_names = Array.make memo_slots ""
let memo_generations = Array.make memo_slots (-1)
let memo_results : obj option array = Array.make memo_slots None

let lookup scope name =
  let n = String.length name in
  let code i = Char.code (String.unsafe_get name i) in
  let h = if n = 0 then 0 else (n * 31 + 5 * code 0 + 3 * code (n - 1) + 17 * code (n / 2)) land (memo_slots - 1) in
  if memo_scopes.(h) == scope && memo_names.(h) == name && memo_generations.(h) = !generation then memo_results.(h)
  else begin
    let r = lookup_tables scope name in
    memo_scopes.(h) <- scope; memo_names.(h) <- name; memo_generations.(h) <- !generation; memo_results.(h) <- r;
    r
  end

(* Data types are looked up past data objects and routines of the same name: a parameter may
   share its name with a type (installed routines do: TPWrite's \Num, PoseInv's Pose). *)
let lookup_type scope name =
  let name = key name in
  let is_type = function Some (Type _) -> true | _ -> false in
  let tables =
    List.map (fun t -> find t name) scope.routine
    @ [ find scope.module_objects name;
        (if scope.in_installed_module then None else find scope.globals name);
        (if scope.in_installed_module then None else find scope.module_names name);
        find scope.installed name ]
  in
  match List.find_opt is_type tables with
  | Some found -> found
  | None -> lookup scope name
