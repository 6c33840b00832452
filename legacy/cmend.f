C=======================================================================
C     CMEND  - AN END OF THE ITEM AT A PLACE OF THE TOUR        (SHARED)
C     SOURCE:  RECONSTRUCTED. PLACE 0 IS WHERE THE TOUR STARTS, PLACE
C              NITM+1 THE START POINT WHERE IT ENDS. (CMOPT2 AND
C              CMOROP WRITE THE SAME LOOK-UP OUT IN THEIR LOOPS.)
C     IP      (INPUT)  INTEGER  THE PLACE, 0..NITM+1
C     IWHICH  (INPUT)  INTEGER  1 = THE END THE TOOL LEAVES IT BY,
C                               2 = THE END THE TOOL ENTERS IT BY
C     IX, IY  (OUTPUT) INTEGER  THE POINT, 0.01 MM
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMEND(IP, IWHICH, IX, IY)
      IMPLICIT NONE
      INTEGER IP, IWHICH, IX, IY
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM), NJOB
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI, NJOB
      SAVE /CMITM/
C     ---- /CMTWK/ WORK SPACE OF THE TOUR: GRID, NEIGHBOURS, QUEUE -----
      INTEGER MXPT, MXCEL, MXNB
      PARAMETER (MXPT = 2 * MXITM, MXCEL = 2 * MXITM, MXNB = 16)
      INTEGER NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1        KQHD, KQN, KWORK, KWMAX,
     2        KQX(MXPT), KQY(MXPT), KCST(MXCEL + 1), KCCN(MXCEL),
     3        KCEL(MXPT), KSLT(MXPT), KNB(MXNB, MXPT), KQUE(MXITM),
     4        LQUE(MXITM)
      COMMON /CMTWK/ NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1               KQHD, KQN, KWORK, KWMAX, KQX, KQY, KCST, KCCN,
     2               KCEL, KSLT, KNB, KQUE, LQUE
      SAVE /CMTWK/
C     ---- LOCAL -------------------------------------------------------
      INTEGER M
C
      IF (IP .EQ. 0) THEN
         IX = KDSX
         IY = KDSY
         RETURN
      END IF
      IF (IP .EQ. NITM + 1) THEN
         IX = KDTX
         IY = KDTY
         RETURN
      END IF
      M = ITOUR(IP)
      IF ((IWHICH .EQ. 1) .EQV. (IORI(M) .EQ. 0)) THEN
         IX = IXX(M)
         IY = IXY(M)
      ELSE
         IX = IEX(M)
         IY = IEY(M)
      END IF
      RETURN
C     END OF CMEND
      END
