C=======================================================================
C     CMFADD - APPEND ONE FRAME TO THE TAPE BEING BUILT        (SHARED)
C     SOURCE:  REPORT, "SOSTAV KADRA": X, Y, DX, DY, TS, K, KK.
C     IX,IY   (INPUT)  INTEGER  TOOL RELATIVE TO THE ARC CENTRE, 0.01 MM
C     IDX,IDY (INPUT)  INTEGER  END MINUS START OF THE FRAME, 0.01 MM
C     ICYC    (INPUT)  INTEGER  0, OR N .GE. 2: THIS FRAME AND THE NEXT
C                               ARE RUN N TIMES
C     K       (INPUT)  INTEGER  10, 20, 11 OR 13
C     ICRD    (INPUT)  INTEGER  THE CARD THAT ASKED FOR THE FRAME, 0 IF
C                               NONE (THE RETURN TO THE START POINT)
C     ICOL    (INPUT)  INTEGER  THE COLUMN TO POINT AT IN A MESSAGE
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMFADD(IX, IY, IDX, IDY, ICYC, K, ICRD, ICOL)
      IMPLICIT NONE
      INTEGER IX, IY, IDX, IDY, ICYC, K, ICRD, ICOL
C     ---- /CMFRT/ THE FRAMES OF THE TAPE BEING PUNCHED ----------------
      INTEGER MXFRM
      PARAMETER (MXFRM = 1000000)
      INTEGER NFR, LFULL, JFX(MXFRM), JFY(MXFRM), JFDX(MXFRM),
     1        JFDY(MXFRM), JFCYC(MXFRM), JFK(MXFRM), JFCRD(MXFRM),
     2        JFCOL(MXFRM)
      COMMON /CMFRT/ NFR, LFULL, JFX, JFY, JFDX, JFDY, JFCYC, JFK,
     1               JFCRD, JFCOL
      SAVE /CMFRT/
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*12 SN
      INTEGER LN
C
      IF (NFR .GE. MXFRM) THEN
         IF (LFULL .EQ. 0) THEN
            CALL CMITOA(MXFRM, SN, LN)
            CALL CMERR('TENZOR', ICRD, 1, 'CAPACITY EXCEEDED: MORE '
     1         // 'THAN ' // SN(1:LN) // ' FRAMES ON ONE TAPE '
     2         // '(PARAMETER MXFRM); SPLIT THE BOARD INTO PACKAGES')
         END IF
         LFULL = 1
         RETURN
      END IF
      NFR = NFR + 1
      JFX(NFR) = IX
      JFY(NFR) = IY
      JFDX(NFR) = IDX
      JFDY(NFR) = IDY
      JFCYC(NFR) = ICYC
      JFK(NFR) = K
      JFCRD(NFR) = ICRD
      JFCOL(NFR) = ICOL
      RETURN
C     END OF CMFADD
      END
