MODULE component_unknown_type_uses
! @format 2
! @section 2.14
! @section 2.11
! @expect semantic-error 9:5
! @description Ruling R-2.14-unknown1: a record component whose type is not known is refused once, at the component's type name; the component stays a component of the record, so its uses and the record's aggregates are not refused again.
  RECORD tray
    num slots;
    gadget holder;
  ENDRECORD
  VAR tray t;
  PROC main()
    t.holder := t.holder;
    t := [4, t.holder];
  ENDPROC
ENDMODULE
