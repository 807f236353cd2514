MODULE function_result_type
! @format 2
! @section 3.11
! @section 4.5
! @expect semantic-error 9:10
! @description The call's value has the function's type; a num result assigned to a string is refused at the call.
  VAR string s;
  PROC main()
    s := polar(1, 2);
  ENDPROC

  FUNC num polar(num dist, num angle)
    RETURN dist * angle;
  ENDFUNC
ENDMODULE
