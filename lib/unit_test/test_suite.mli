(** [rapid-sem test] (doc/testing.md): the modules given form one task buffer; each parameterless
    procedure whose name begins with [test_] (letter case aside, §2.3) in them is a test, run
    from its first statement in a fresh controller (its own module data, clock, signals and
    robot) with the assertions of lib/typing/installed/unit_test.sys installed. A test passes
    when it ends (§4.12: the end of the procedure, RETURN, EXIT), and fails when it stops: a
    failed assertion, an error no handler takes, a limit (doc/rulings.md R-test-c). *)

(** {1 The modules} *)

val module_files : string list -> (string list, string) result
(** The files given, each folder replaced by the RAPID modules below it (.mod, .sys, .modx,
    .sysx, letter case aside), in name order. Standard input ([-]) is refused: its directives and
    its tests are read before the task buffer is loaded. *)

val directive_options : Rapid_run.Run_options.t -> string -> (Rapid_run.Run_options.t, string) result
(** The options of the tests of this file: those given, with what its [!rapid-sem:] comment
    lines ask for ([--io FILE], [--robot FILE], [--max-time S], [--statement-time S]; a file
    named relative to the module's folder). An [Error] says FILE:LINE:COL and what is wrong. *)

(** {1 The tests} *)

type test = {
  name : string;                          (** as declared *)
  module_name : string;
  file : string;                          (** the file that declares it *)
  line : int;
  col : int;                              (** where the declaration begins *)
  options : Rapid_run.Run_options.t;      (** with its module's directives *)
}

type suite = {
  files : string list;                    (** the task buffer *)
  tests : test list;                      (** in the order of the files, then of declaration *)
  test_modules : string list;             (** the modules that declare a test *)
  coverage : Test_coverage.t;             (** the routines of the other modules, at 0 *)
  loads : (Rapid_run.Run_options.t * Rapid_load.Session.loaded) list;
      (** the task buffer loaded once per set of options its test modules ask for *)
}

val discover :
  notify:(Rapid_run.Run_setup.notice -> unit) -> Rapid_run.Run_options.t -> string list ->
  (suite, Rapid_run.Run_setup.failure) result
(** The task buffer of these files loaded once with each distinct set of options its modules
    ask for (its static errors, a directive's mistakes, are failures before any test runs), and
    its tests found. *)

val filter : Str.regexp -> suite -> suite
(** Only the tests whose name the expression matches (anywhere in it, case as written). *)

(** {1 Running them} *)

type verdict =
  | Passed
  | Failed of { at : string option; message : string }
      (** [at]: FILE:LINE:COL of the failed assertion or of the error; for a failure that has no
          place of its own (--max-time, a deadlock), the test's name in its declaration *)

type result = {
  test : test;
  verdict : verdict;
  time : float;                           (** the virtual time the test took, in seconds *)
  output : string list;                   (** what it wrote with TPWrite *)
  hits : Test_coverage.portable option;   (** with coverage *)
}

val run_test : coverage:bool -> engine:[ `Machine | `Closure ] -> suite -> test -> result
(** One test in its fresh controller. With [coverage], on the machine, whose steps say what the
    test reached. *)

val run :
  ?jobs:int -> coverage:bool -> engine:[ `Machine | `Closure ] -> on_result:(int -> result -> unit) -> suite ->
  result list
(** Every test, in [jobs] child processes (default 1: in this one), each result handed to
    [on_result] with its index as it arrives; the list is in the order of the tests. *)
