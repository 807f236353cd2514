MODULE <ID>
! @section 2.9
! @section 2.3
! @expect ok
! @description <ID> stands for an identifier: module, type, component, data, routine, label, function and argument names.
  RECORD <ID>
    <ID> <ID>;
  ENDRECORD
  VAR <ID> <ID>;
  PROC <ID>()
    <ID>:
    x := <ID>(1);
    <ID> <ID> := 1;
    GOTO <ID>;
  ENDPROC
ENDMODULE
