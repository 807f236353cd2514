(* Sources: the kernel manual (§2.16), issue 3 ("The installed environment"), and
   ../shared/reference/installed-facts.md; entries taken from memory of the RobotWare data
   type pages say UNCERTAIN. *)

let atomic_types : (string * Types.value_class * Types.data_type option) list = [
  (* §2.16 names signaldi as the example of a semi-value type with associated type num
     (IF di1 = 1 reads it, di1 := 1 is refused). *)
  ("signaldi", Types.Semi_value, Some Types.Num);
  (* The other signal types behave alike (issue 3): in value context a signal reads as its
     current value. *)
  ("signaldo", Types.Semi_value, Some Types.Num);
  ("signalai", Types.Semi_value, Some Types.Num);
  ("signalao", Types.Semi_value, Some Types.Num);
  (* Group signals: num, not dnum. installed-facts.md §1 says a group wider than 23 bits must
     be read with GInputDnum and written with SetGO ... \Dvalue "because num cannot hold it
     exactly": the signal itself, used in an expression, gives a num, and the dnum value is
     reached only through those routines. *)
  ("signalgi", Types.Semi_value, Some Types.Num);
  ("signalgo", Types.Semi_value, Some Types.Num);
  (* §2.16 names iodev as the example of a non-value type: changed only by installed
     routines (Open, Close, Write, ...). *)
  ("iodev", Types.Non_value, None);
  (* A socket is a device like iodev, handled only by the Socket... routines (issue 3). *)
  ("socketdev", Types.Non_value, None);
  (* A clock is read with ClkRead and changed with ClkReset/ClkStart/ClkStop only: no value
     to compare or assign (UNCERTAIN: RobotWare's clock page says it is non-value). *)
  ("clock", Types.Non_value, None);
  (* The buffer of SocketSend/SocketReceive \RawData, filled and read by PackRawBytes and
     UnpackRawBytes (UNCERTAIN). *)
  ("rawbytes", Types.Non_value, None);
  (* The identity of a program task, \TaskRef of CRobT and CJointT (UNCERTAIN). *)
  ("taskid", Types.Non_value, None);
  (* The event that started the current trap, read by GetTrapData/ReadErrData after IError
     (installed-facts.md §6 names trapdata; its class is UNCERTAIN). *)
  ("trapdata", Types.Non_value, None);
  (* The following are declared in RAPID only as the types of installed routines' parameters
     (io.sys, system.sys, egm.sys, motion.sys); RobotWare's data type pages call each a
     non-value type (UNCERTAIN: from memory of those pages). *)
  (* A directory opened with OpenDir. *)
  ("dir", Types.Non_value, None);
  (* The meeting point of WaitSyncTask and SyncMoveOn. *)
  ("syncident", Types.Non_value, None);
  (* A trigger on the path, defined by TriggIO and used by TriggL. *)
  ("triggdata", Types.Non_value, None);
  (* A block of the program (task, module, routine) for GetDataVal and SetDataVal. *)
  ("datapos", Types.Non_value, None);
  (* An EGM process. *)
  ("egmident", Types.Non_value, None);
  (* A mechanical unit of the configuration (ROB_1, ...). *)
  ("mecunit", Types.Non_value, None);
  (* A slot of the RAPID Message Queue, found with RMQFindSlot (cell.sys). *)
  ("rmqslot", Types.Non_value, None);
  (* A message taken from the queue by RMQGetMessage or RMQReadWait (cell.sys). *)
  ("rmqmessage", Types.Non_value, None);
  (* A world zone's volume, defined by WZBoxDef and the like (cell.sys). *)
  ("shapedata", Types.Non_value, None);
]

let find name =
  List.find_map
    (fun (atomic_name, atomic_class, associated) ->
      if Types.same_name atomic_name name then
        Some (Types.Installed_atomic { Types.atomic_name; atomic_class; associated })
      else None)
    atomic_types

(* §2.16: "半值对象(类型)可拒绝'按值'读取或更新 … 由于sig1表示一项输入器件,因此,sig1拒绝下列
   赋值": a semi-value type may refuse reading or updating by value; an input signal refuses
   assignment. Output signals accept it (the table's legal cell). *)
let refuses_update = [ "signaldi"; "signalai"; "signalgi" ]
