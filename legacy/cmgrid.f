C=======================================================================
C     CMGRID - BUCKET THE ENDS LISTED IN KCEL(1..NP) ON A GRID  (SHARED)
C     SOURCE:  RECONSTRUCTED. SQUARE CELLS OF ABOUT NPC ENDS EACH
C              OVER THE BOX OF THE ENDS, COUNTING NSZ ENDS (MORE THAN
C              ARE LISTED WHEN ENDS AT THE SAME POINT AS ONE LISTED ARE
C              LEFT OUT, SO THAT THE CELLS ARE THE SAME SIZE AS WITH
C              THEM); KCEL IS REWRITTEN CELL BY CELL,
C              KCST(C) IS WHERE CELL C STARTS, KCCN(C) HOW MANY OF ITS
C              ENDS ARE STILL LIVE, KSLT(P) WHERE END P STANDS.
C     NP      (INPUT)  INTEGER  NUMBER OF ENDS LISTED
C     NSZ     (INPUT)  INTEGER  HOW MANY ENDS THE CELLS ARE SIZED FOR
C     NPC     (INPUT)  INTEGER  ABOUT HOW MANY ENDS A CELL SHOULD HOLD
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMGRID(NP, NSZ, NPC)
      IMPLICIT NONE
      INTEGER NP, NSZ, NPC
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
      INTEGER I, IP, IC, IX1, IX2, IY1, IY2, NC
      DOUBLE PRECISION W, H, CS
C
      IX1 = KQX(KCEL(1))
      IX2 = IX1
      IY1 = KQY(KCEL(1))
      IY2 = IY1
      DO 10 I = 1, NP
         IP = KCEL(I)
         IX1 = MIN(IX1, KQX(IP))
         IX2 = MAX(IX2, KQX(IP))
         IY1 = MIN(IY1, KQY(IP))
         IY2 = MAX(IY2, KQY(IP))
   10 CONTINUE
      KGX0 = IX1
      KGY0 = IY1
      W = MAX(IX2 - IX1, 1)
      H = MAX(IY2 - IY1, 1)
      CS = MAX(1.0D0, SQRT(W * H * NPC / MAX(NSZ, 1)))
      CS = MAX(CS, MAX(W, H) / 2000.0D0)
   20 CONTINUE
      KGCS = INT(CS)
      NGX = (IX2 - IX1) / KGCS + 1
      NGY = (IY2 - IY1) / KGCS + 1
      IF (DBLE(NGX) * NGY .GT. MXCEL) THEN
         CS = CS * 1.5D0
         GOTO 20
      END IF
      NC = NGX * NGY
C     ---- COUNT, PLACE ------------------------------------------------
      DO 30 IC = 1, NC
         KCCN(IC) = 0
   30 CONTINUE
      DO 40 I = 1, NP
         IP = KCEL(I)
         CALL CMCELL(KQX(IP), KQY(IP), IC)
         KSLT(IP) = IC
         KCCN(IC) = KCCN(IC) + 1
         KNB(1, I) = IP
   40 CONTINUE
      KCST(1) = 1
      DO 50 IC = 1, NC
         KCST(IC + 1) = KCST(IC) + KCCN(IC)
         KCCN(IC) = 0
   50 CONTINUE
      DO 60 I = 1, NP
         IP = KNB(1, I)
         IC = KSLT(IP)
         KCEL(KCST(IC) + KCCN(IC)) = IP
         KSLT(IP) = KCST(IC) + KCCN(IC)
         KCCN(IC) = KCCN(IC) + 1
   60 CONTINUE
      RETURN
C     END OF CMGRID
      END
