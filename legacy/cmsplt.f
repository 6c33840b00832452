C=======================================================================
C     CMSPLT - SPLIT THE LONG STRAIGHT FRAMES OF THE TAPE       (SHARED)
C     SOURCE:  SEED 004 (SEE CMSPL1). WITH A FRAME LIMIT ON THE
C              P CARD, EVERY STRAIGHT FRAME FROM I1 ON WHOSE DX OR DY IS
C              LONGER IS CUT BY CMSPL1. A CYCLE WITH A LONG FRAME IS RUN
C              OUT INTO ITS FRAMES FIRST. AN ARC CANNOT BE CUT THIS WAY:
C              AN ARC FRAME BEYOND THE LIMIT IS AN ERROR OF ITS CARD.
C              THE FRAMES ARE MOVED TO THE TOP OF THE TABLE AND READ
C              BACK FROM THERE AS THE NEW ONES ARE WRITTEN BELOW THEM.
C     I1      (INPUT)  INTEGER  THE FIRST FRAME THAT MAY BE SPLIT
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMSPLT(I1)
      IMPLICIT NONE
      INTEGER I1
C     ---- /TZPKG/ THE PACKAGE: P CARD PARAMETERS, ITS CARD IMAGES ---
      INTEGER MXCRD
      PARAMETER (MXCRD = 200000)
      INTEGER LPKG, ICFST, NPCRD, NPERR, LECHO, IPCRD, LGEOM,
     1        IX0, IY0, IWT(3), IDMAX, ISCN, ISCD, ICODE, IORD, IFMAX,
     2        NPWRN
      COMMON /TZPKG/ LPKG, ICFST, NPCRD, NPERR, LECHO, IPCRD, LGEOM,
     1               IX0, IY0, IWT, IDMAX, ISCN, ISCD, ICODE, IORD,
     2               IFMAX, NPWRN
      CHARACTER*18 PKNAME
      CHARACTER*24 PKFILE
      CHARACTER*80 CIMG(MXCRD)
      COMMON /TZPKGC/ PKNAME, PKFILE, CIMG
      SAVE /TZPKG/, /TZPKGC/
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
      INTEGER I, J, N, NTOP, JTOP, IREP, NREP, NF, L
      LOGICAL LLONG
C     THE ARCS OVER THE LIMIT OF ONE CARD ARE ONE ERROR: ITS CARD, AND
C     THE LONGEST NUMBER OF ITS RUN OF FRAMES (IAMAX)
      INTEGER IACRD, IAMAX
      CHARACTER*12 S1, S2
      INTEGER L1, L2
C
      IF (IFMAX .LE. 0 .OR. NFR .LT. I1) RETURN
C     ---- ANYTHING TO DO? ARCS BEYOND THE LIMIT ARE ERRORS ------------
      LLONG = .FALSE.
      IACRD = 0
      DO 10 I = I1, NFR
         IF (JFK(I) .EQ. 11 .OR. JFK(I) .EQ. 13) THEN
            IF (MAX(ABS(JFX(I)), ABS(JFY(I)), ABS(JFDX(I)),
     1              ABS(JFDY(I))) .GT. IFMAX .AND.
     2          JFCRD(I) .NE. IACRD) THEN
               IACRD = JFCRD(I)
               IAMAX = 0
               DO 5 J = I, NFR
                  IF (JFCRD(J) .NE. IACRD) GOTO 6
                  IF (JFK(J) .EQ. 11 .OR. JFK(J) .EQ. 13)
     1               IAMAX = MAX(IAMAX, ABS(JFX(J)), ABS(JFY(J)),
     2                           ABS(JFDX(J)), ABS(JFDY(J)))
    5          CONTINUE
    6          CONTINUE
               CALL CMITOA(IAMAX, S1, L1)
               CALL CMITOA(IFMAX, S2, L2)
               CALL CMERR('TENZOR', IACRD, JFCOL(I), 'AN ARC OF THIS '
     1            // 'CARD MOVES ' // S1(1:L1) // ' PULSES, MORE THAN '
     2            // 'THE FRAME LIMIT FMAX OF THE P CARD (' // S2(1:L2)
     3            // '); ARCS ARE NOT SPLIT: FMAX MUST BE ' // S1(1:L1)
     4            // ' OR MORE')
            END IF
         ELSE IF (MAX(ABS(JFDX(I)), ABS(JFDY(I))) .GT. IFMAX) THEN
            LLONG = .TRUE.
         END IF
   10 CONTINUE
      IF (.NOT. LLONG) RETURN
C     ---- MOVE THE FRAMES TO THE TOP OF THE TABLE ---------------------
      N = NFR - I1 + 1
      IF (NFR + N .GT. MXFRM) THEN
         CALL CMITOA(MXFRM, SN, LN)
         CALL CMERR('TENZOR', JFCRD(I1), 1, 'CAPACITY EXCEEDED: NO '
     1      // 'ROOM IN THE FRAME TABLE OF ' // SN(1:LN) // ' FRAMES '
     2      // 'TO SPLIT THE FRAMES OF ONE TAPE (PARAMETER MXFRM)')
         LFULL = 1
         RETURN
      END IF
      NTOP = MXFRM - N + 1
      DO 20 I = N, 1, -1
         CALL CMFCPY(I1 + I - 1, NTOP + I - 1)
   20 CONTINUE
      NFR = I1 - 1
      JTOP = NTOP
C     ---- AND BACK, SPLIT ---------------------------------------------
   30 CONTINUE
      IF (JTOP .GT. MXFRM .OR. LFULL .NE. 0) RETURN
      NF = 1
      NREP = 1
      IF (JFCYC(JTOP) .GE. 2 .AND. JTOP .LT. MXFRM) THEN
         NF = 2
         NREP = JFCYC(JTOP)
         IF (MAX(ABS(JFDX(JTOP)), ABS(JFDY(JTOP)), ABS(JFDX(JTOP+1)),
     1           ABS(JFDY(JTOP+1))) .LE. IFMAX) NREP = 1
      END IF
      IF (NF .EQ. 2 .AND. NREP .EQ. 1) THEN
C        A CYCLE WITHIN THE LIMIT STAYS AS IT IS
         DO 35 L = 0, 1
            NFR = NFR + 1
            CALL CMFCPY(JTOP + L, NFR)
   35    CONTINUE
      ELSE
         DO 50 IREP = 1, NREP
            DO 40 J = JTOP, JTOP + NF - 1
C              THE TABLE MUST NOT GROW INTO THE FRAMES NOT YET READ
               IF (NFR + (MAX(ABS(JFDX(J)), ABS(JFDY(J))) / IFMAX + 1)
     1             .GE. JTOP) THEN
                  CALL CMITOA(MXFRM, SN, LN)
                  CALL CMERR('TENZOR', JFCRD(J), 1, 'CAPACITY EXCEEDED:'
     1               // ' MORE THAN ' // SN(1:LN) // ' FRAMES ON ONE '
     2               // 'TAPE AFTER SPLITTING (PARAMETER MXFRM)')
                  LFULL = 1
                  RETURN
               END IF
               IF (JFK(J) .EQ. 10 .OR. JFK(J) .EQ. 20) THEN
                  CALL CMSPL1(JFDX(J), JFDY(J), JFK(J), JFCRD(J),
     1                        JFCOL(J))
               ELSE
                  NFR = NFR + 1
                  CALL CMFCPY(J, NFR)
                  JFCYC(NFR) = 0
               END IF
   40       CONTINUE
   50    CONTINUE
      END IF
      JTOP = JTOP + NF
      GOTO 30
C     END OF CMSPLT
      END
