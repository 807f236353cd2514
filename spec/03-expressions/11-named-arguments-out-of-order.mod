MODULE named_arguments_out_of_order
! @format 2
! @section 3.11
! @expect semantic-error 8:16
! @description Arguments stand in the order of the parameters even when named; refused at the first argument out of place.
  VAR num x;
  PROC main()
    x := polar(angle := 0.785398, dist := 3.937);
  ENDPROC

  FUNC num polar(num dist, num angle)
    RETURN dist * angle;
  ENDFUNC
ENDMODULE
