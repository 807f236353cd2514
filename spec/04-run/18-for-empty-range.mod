MODULE for_empty_range
! @format 3
! @section 4.18
! @expect ok
! @description With an explicit step that leads away from TO, the FROM value itself is outside the range and the body never runs (reading: the range check of section 4.18 applies to the first value too; "(non-first)" qualifies the update of the loop variable, not the check).
! @output after
! @exit 0
  PROC main()
    FOR i FROM 1 TO 0 STEP 1 DO
      TPWrite "wrong up";
    ENDFOR
    FOR i FROM 0 TO 1 STEP -1 DO
      TPWrite "wrong down";
    ENDFOR
    TPWrite "after";
  ENDPROC
ENDMODULE
