MODULE cell
! @format 2
! @section 2.20
! @section 2.18
! @expect semantic-error b.mod:7:12
! @description TASK and system-global persistents are both global for the scope rules (section 2.18); two in different modules with one name are refused at the later one.
  PERS num state;
ENDMODULE
