MODULE if_statement
! @section 4.16
! @expect ok
! @description The example of section 4.16, and several ELSEIF clauses and <EIT> without ELSE.
  VAR num counter;
  PROC main()
    IF counter > 100 THEN
      counter := 100;
    ELSEIF counter < 0 THEN
      counter := 0;
    ELSE
      counter := counter + 1;
    ENDIF
    IF counter > 1 THEN
    ELSEIF counter > 2 THEN
    ELSEIF counter > 3 THEN
    <EIT>
    ENDIF
  ENDPROC
ENDMODULE
