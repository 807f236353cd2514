MODULE switch_arguments
! @format 2
! @section 3.11
! @expect ok
! @description Section 3.11: cosine(45) and cosine(0.785398\rad); a switch argument has no value.
  VAR num c;
  PROC main()
    c := cosine(45);
    c := cosine(0.785398\rad);
  ENDPROC

  FUNC num cosine(num angle \switch rad)
    IF Present(rad) RETURN angle;
    RETURN angle / 57.29578;
  ENDFUNC
ENDMODULE
