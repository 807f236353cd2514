type services = {
  fs : string option; fs_quota : int option; net : string list; map_address : string list; egm_device : string list;
  operator : string option }

type controller = {
  io : string option; statement_time : float; max_time : float; epoch : float; services : services;
  robotware : Rapid_syntax.Robotware.t option; units : string list }

type t = {
  max_steps : int; allow_unknown : bool; stub_unmodelled : bool; limits : Limits.t; controller : controller;
  robot : string option; base_frames : string list }

type tasks = {
  files : string list; entries : string list; tasks : string list; schedule : int option;
  motion_task : string option }
