C=======================================================================
C     CMKDEP - THE NEAR ENDS OF THE TOUR'S TWO FIXED POINTS     (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMTOUR). THE TOUR STARTS AT THE
C              TOOL'S START (PLACE 0) AND ENDS AT THE START POINT
C              (PLACE NITM+1). NEITHER IS AN END OF AN ITEM, SO NEITHER
C              HAS NEAR ENDS OF ITS OWN IN KNB, AND NO MOVE WAS EVER
C              LOOKED FOR FROM THEIR SIDE: ON A BOARD WHOSE START POINT
C              LIES OFF THE PADS, THE FIRST AND LAST MOVES OF THE TOUR
C              STAYED LONG UNTIL A KICK HAPPENED TO CUT THEM. HERE THE
C              MXNB NEAREST ENDS OF EACH (NEAREST FIRST, TIES BY THE
C              LOWER END) ARE FOUND BY LOOKING AT EVERY END ONCE; THE
C              EXIT OF AN ITEM WHOSE ENDS ARE ONE POINT IS LEFT OUT, AS
C              IN CMKNN. CMOPT2 USES THEM.
C     NP      (INPUT)  INTEGER  THE ENDS, 2 * NITM
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMKDEP(NP)
      IMPLICIT NONE
      INTEGER NP
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
C     ---- /CMTWE/ THE NEAR ENDS OF THE TOOL'S START (1) AND OF THE
C     START POINT (2), AND THEIR LENGTHS ------------------------------
      INTEGER KENB(MXNB, 2), NENB(2)
      DOUBLE PRECISION DENB(MXNB, 2)
      COMMON /CMTWE/ DENB, KENB, NENB
      SAVE /CMTWE/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I, K, IX, IY
      DOUBLE PRECISION D
C
      DO 30 K = 1, 2
         IF (K .EQ. 1) THEN
            IX = KDSX
            IY = KDSY
         ELSE
            IX = KDTX
            IY = KDTY
         END IF
         NENB(K) = 0
         DO 10 I = 1, NP
            IF (MOD(I, 2) .EQ. 0) THEN
               IF (KQX(I) .EQ. KQX(I - 1) .AND.
     1             KQY(I) .EQ. KQY(I - 1)) GOTO 10
            END IF
            D = (DBLE(IX) - KQX(I))**2 + (DBLE(IY) - KQY(I))**2
            CALL CMKINS(KENB(1, K), DENB(1, K), NENB(K), MXNB, I, D)
   10    CONTINUE
         DO 20 I = 1, NENB(K)
            DENB(I, K) = SQRT(DENB(I, K))
   20    CONTINUE
   30 CONTINUE
      RETURN
C     END OF CMKDEP
      END
