C=======================================================================
C     CMVEND - THE END AT A PLACE OF THE CYCLE AS A MOVE BEING TRIED
C              WOULD LEAVE IT                                   (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMVPOS): THE PLACE IS MAPPED BACK
C              THROUGH THE LISTED REVERSALS, LAST FIRST.
C     IQ      (INPUT)  INTEGER  THE PLACE, 1..NLN
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      INTEGER FUNCTION CMVEND(IQ)
      IMPLICIT NONE
      INTEGER IQ
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM)
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI
      SAVE /CMITM/
C     ---- /CMTWK/ WORK SPACE OF THE TOUR: GRID, NEIGHBOURS, QUEUE -----
      INTEGER MXPT, MXCEL, MXNB
      PARAMETER (MXPT = 2 * MXITM + 2, MXCEL = 2 * MXITM, MXNB = 16)
      INTEGER NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1        KQHD, KQN, KWORK, KWMAX,
     2        KQX(MXPT), KQY(MXPT), KCST(MXCEL + 1), KCCN(MXCEL),
     3        KCEL(MXPT), KSLT(MXPT), KNB(MXNB, MXPT), KQUE(MXITM),
     4        LQUE(MXITM)
      COMMON /CMTWK/ NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1               KQHD, KQN, KWORK, KWMAX, KQX, KQY, KCST, KCCN,
     2               KCEL, KSLT, KNB, KQUE, LQUE
      SAVE /CMTWK/
C     ---- /CMTLK/ THE TOUR AS A CYCLE OF ENDS, FOR LIN-KERNIGHAN ------
      INTEGER NLN, LQH, LQN, LTR(MXPT), LPS(MXPT), LMT(MXPT),
     1        LQU(MXPT), LQF(MXPT)
      COMMON /CMTLK/ NLN, LQH, LQN, LTR, LPS, LMT, LQU, LQF
      SAVE /CMTLK/
C     ---- /CMTLV/ THE REVERSALS OF A MOVE BEING TRIED (CMLKST) --------
      INTEGER MXDEP
      PARAMETER (MXDEP = 3)
      INTEGER NVR, KRA(MXDEP), KRB(MXDEP)
      COMMON /CMTLV/ NVR, KRA, KRB
      SAVE /CMTLV/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I, IP, IOFF, LEN
C
      IF (NVR .EQ. 0) THEN
         CMVEND = LTR(IQ)
         RETURN
      END IF
      IP = IQ
      DO 10 I = NVR, 1, -1
         IOFF = MOD(IP - KRA(I) + NLN, NLN)
         LEN = MOD(KRB(I) - KRA(I) + NLN, NLN)
         IF (IOFF .LE. LEN) IP = MOD(KRA(I) - 1 + LEN - IOFF, NLN) + 1
   10 CONTINUE
      CMVEND = LTR(IP)
      RETURN
C     END OF CMVEND
      END
