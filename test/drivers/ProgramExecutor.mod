MODULE ProgramExecutor
    ! A motion-program executor: it reads a binary motion program from HOME:/program.bin and
    ! executes it record by record, reporting each record done on the FlexPendant (TPWrite).
    ! The format is our own, little-endian:
    !   header, 12 bytes: "RSMP" (4 ASCII bytes), int32 version (1), int32 number of records;
    !   records, 32 bytes each: int32 opcode, then 7 float32 arguments:
    !     1 MoveL  x y z q1 q2 q3 q4   (tool0 in wobj0, mm and quaternion)
    !     2 MoveJ  x y z q1 q2 q3 q4
    !     3 WaitTime seconds (the other six unused)
    ! A program is read whole (a rawbytes holds 1024 bytes: at most 31 records).
    LOCAL CONST num HEADER_SIZE := 12;
    LOCAL CONST num RECORD_SIZE := 32;
    LOCAL VAR rawbytes program;

    PROC main()
        VAR iodev file;
        VAR string magic;
        VAR num version;
        VAR num count;
        VAR robtarget here;
        Open "HOME:/program.bin", file \Read \Bin;
        ReadRawBytes file, program;
        Close file;
        UnpackRawBytes program, 1, magic \ASCII:=4;
        UnpackRawBytes program, 5, version \IntX:=DINT;
        UnpackRawBytes program, 9, count \IntX:=DINT;
        IF magic <> "RSMP" OR version <> 1 OR RawBytesLen(program) <> HEADER_SIZE + RECORD_SIZE * count THEN
            TPWrite "not a motion program";
            RETURN;
        ENDIF
        TPWrite "program of records: " \Num:=count;
        ConfJ \Off;
        ConfL \Off;
        FOR i FROM 1 TO count DO
            Execute i, HEADER_SIZE + RECORD_SIZE * (i - 1) + 1;
        ENDFOR
        here := CRobT(\Tool:=tool0 \WObj:=wobj0);
        TPWrite "final position " + NumToStr(here.trans.x, 1) + " " + NumToStr(here.trans.y, 1) + " "
            + NumToStr(here.trans.z, 1);
    ENDPROC

    ! The record at byte [at]: its opcode and arguments, executed, then reported.
    LOCAL PROC Execute(num number, num at)
        VAR num opcode;
        VAR num a{7};
        VAR robtarget target;
        UnpackRawBytes program, at, opcode \IntX:=DINT;
        FOR k FROM 1 TO 7 DO
            UnpackRawBytes program, at + 4 * k, a{k} \Float4;
        ENDFOR
        IF opcode = 1 OR opcode = 2 THEN
            target := CRobT(\Tool:=tool0 \WObj:=wobj0);
            target.trans := [a{1}, a{2}, a{3}];
            target.rot := NOrient([a{4}, a{5}, a{6}, a{7}]);
        ENDIF
        TEST opcode
        CASE 1:
            MoveL target, v300, fine, tool0 \WObj:=wobj0;
            TPWrite "record " + NumToStr(number, 0) + " MoveL done";
        CASE 2:
            MoveJ target, v300, fine, tool0 \WObj:=wobj0;
            TPWrite "record " + NumToStr(number, 0) + " MoveJ done";
        CASE 3:
            WaitTime a{1};
            TPWrite "record " + NumToStr(number, 0) + " WaitTime " + NumToStr(a{1}, 2) + " done";
        DEFAULT:
            TPWrite "record " + NumToStr(number, 0) + " unknown opcode " + NumToStr(opcode, 0);
        ENDTEST
    ENDPROC
ENDMODULE
