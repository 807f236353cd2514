MODULE component_unknown_type_allowed
! @format 2
! @section 2.14
! @section 13
! @options allow-unknown
! @expect ok
! @description Ruling R-2.14-unknown1: with --allow-unknown, a record component of a type neither declared nor installed is a component of unknown type: the record keeps all its components in their order, and uses of that component (as target, operand, argument, aggregate member) are not judged.
  RECORD tray
    num slots;
    gadget holder;
    num weight;
  ENDRECORD
  VAR tray t;
  VAR num n;
  PROC main()
    t.holder := 3;
    n := t.holder + t.weight;
    t := [4, t.holder, 2.5];
    TPWrite "slots" \Num:=t.slots;
  ENDPROC
ENDMODULE
