MODULE assignment_targets
! @format 2
! @section 4.5
! @expect ok
! @description Targets of value type: a variable, a persistent, a component, an element, and parameters of every mode; <VAR> stands for a target.
  VAR num count;
  PERS num total := 0;
  VAR pos home;
  VAR num table{3};
  VAR num temp;
  PROC main()
    count := count + 1;
    total := count;
    home.x := 1;
    table{2} := temp;
    <VAR> := temp + 5;
  ENDPROC
  PROC update(num a, VAR num b, PERS num c, INOUT num d)
    a := 1;
    b := 2;
    c := 3;
    d := 4;
  ENDPROC
ENDMODULE
