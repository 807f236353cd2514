MODULE record_component_unknown_type
! @format 2
! @section 2.14
! @section 2.11
! @expect semantic-error 9:5
! @description A record component whose type is not known is refused at the component's type name.
  RECORD tray
    num slots;
    gadget holder;
  ENDRECORD
ENDMODULE
