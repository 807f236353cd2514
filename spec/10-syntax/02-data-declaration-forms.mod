MODULE data_declaration_forms
! @section 2.18
! @expect ok
! @description <data declaration> ::= [LOCAL] (VAR | PERS | CONST declaration) | TASK (VAR | PERS declaration) | <comment> | <DDN>.
  VAR num v1;
  LOCAL VAR num v2;
  TASK VAR num v3;
  PERS num p1 := 0;
  LOCAL PERS num p2 := 0;
  TASK PERS num p3 := 0;
  CONST num c1 := 1;
  LOCAL CONST num c2 := 2;
  ! a comment
  <DDN>
ENDMODULE
