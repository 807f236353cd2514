MODULE cell
! @format 2
! @section 2.12
! @section 13
! @expect semantic-error b.mod:7:7
! @description The scope of a LOCAL type definition is its module; another module's declaration of that type is refused at the type name.
  VAR gripdata grip;
ENDMODULE
