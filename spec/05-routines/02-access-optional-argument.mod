MODULE access_optional_argument
! @format 2
! @section 5.2
! @expect semantic-error 13:16
! @description The access-mode table holds for optional arguments too: a constant for an optional VAR parameter is refused at the backslash.
  CONST num start := 0;
  VAR num n;
  PROC count_up(num increment \VAR num counter)
    IF Present(counter) counter := counter + increment;
  ENDPROC
  PROC main()
    count_up 1 \counter:=n;
    count_up 1 \counter:=start;
  ENDPROC
ENDMODULE
