MODULE local_record_in_its_module
! @format 2
! @section 2.14
! @section 2.12
! @expect ok
! @description A LOCAL record type (section 2.11's example) is usable in the module that defines it.
  LOCAL RECORD object
    num usecount;
    string name;
  ENDRECORD
  VAR object obj := [0, "gripper"];
  PROC main()
    obj.usecount := obj.usecount + 1;
  ENDPROC
ENDMODULE
