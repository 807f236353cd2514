MODULE unknown_component_type_reached
! @format 3
! @section 2.14
! @section 13
! @options allow-unknown
! @expect ok
! @description Ruling R-2.14-unknown1: with --allow-unknown a record keeps a component of a type neither declared nor installed; its other components run as usual, and reaching the unknown one is ERR_REFUNKDAT, as reaching an unknown data object is (ch. 12).
! @output slots=4 weight=2.5
! @output refunkdat=TRUE
! @exit 0
  RECORD tray
    num slots;
    gadget holder;
    num weight;
  ENDRECORD
  VAR tray t := [4, 0, 2.5];
  VAR num n;
  PROC main()
    TPWrite "slots=" + NumToStr(t.slots, 0) + " weight=" \Num:=t.weight;
    n := t.holder + 1;
    TPWrite "not after the unknown component";
  ERROR
    TPWrite "refunkdat=" \Bool:=ERRNO = ERR_REFUNKDAT;
    RETURN;
  ENDPROC
ENDMODULE
