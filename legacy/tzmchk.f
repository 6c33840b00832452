C=======================================================================
C     TZMCHK - CYCLES OF THE M FRAMES NEED THEIR SECOND FRAME  (TENZOR)
C     SOURCE:  REPORT, "SOSTAV KADRA": "TS - TSIKL, PRIKAZ NA
C              TSIKLICHESKUYU OBRABOTKU DVUKH POSLEDOVATEL'NYKH KADROV"
C              (A CYCLE REPEATS TWO CONSECUTIVE FRAMES). ON EACH TAPE A
C              FRAME WITH CYC MUST BE FOLLOWED BY AN M FRAME OF THE SAME
C              TAPE, AND THAT SECOND FRAME MAY NOT CARRY CYC ITSELF.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZMCHK
      IMPLICIT NONE
C     ---- /CMMAN/ MANUAL FRAMES OF M CARDS, IN DECK ORDER -------------
      INTEGER MXMAN
      PARAMETER (MXMAN = 20000)
      INTEGER NMAN, MMTAP(MXMAN), MMX(MXMAN), MMY(MXMAN), MMDX(MXMAN),
     1        MMDY(MXMAN), MMCYC(MXMAN), MMK(MXMAN), MMCRD(MXMAN)
      COMMON /CMMAN/ NMAN, MMTAP, MMX, MMY, MMDX, MMDY, MMCYC, MMK,
     1               MMCRD
      SAVE /CMMAN/
C     ---- LOCAL -------------------------------------------------------
C     LAST(T) THE INDEX OF THE LAST M FRAME SEEN ON TAPE T IF IT OPENED
C     A CYCLE, ELSE 0
      INTEGER LAST(3), I, IT
      CHARACTER*1 TNAME(3)
      DATA TNAME / 'S', 'B', 'L' /
C
      LAST(1) = 0
      LAST(2) = 0
      LAST(3) = 0
      DO 10 I = 1, MIN(NMAN, MXMAN)
         IT = MMTAP(I)
         IF (LAST(IT) .NE. 0 .AND. MMCYC(I) .NE. 0) THEN
            CALL CMERR('TENZOR', MMCRD(I), 51, 'CYC ON THE SECOND FRAME'
     1         // ' OF A CYCLE; THE FRAME BEFORE ON THIS TAPE ALREADY '
     2         // 'REPEATS THIS ONE')
            LAST(IT) = 0
         ELSE IF (LAST(IT) .NE. 0) THEN
            LAST(IT) = 0
         ELSE IF (MMCYC(I) .NE. 0) THEN
            LAST(IT) = I
         END IF
   10 CONTINUE
      DO 20 IT = 1, 3
         IF (LAST(IT) .NE. 0) CALL CMERR('TENZOR', MMCRD(LAST(IT)), 51,
     1      'CYC ON THE LAST M FRAME OF TAPE ' // TNAME(IT) // '; A '
     2      // 'CYCLE NEEDS A SECOND M FRAME ON THE SAME TAPE')
   20 CONTINUE
      RETURN
C     END OF TZMCHK
      END
