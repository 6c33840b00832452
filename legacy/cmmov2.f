C=======================================================================
C     CMMOV2 - A 2-OPT MOVE OF THE CYCLE OF ENDS                (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMLK). THE MOVES IA-IB AND IC-ID ARE
C              REPLACED BY IA-IC AND IB-ID: THE PATH FROM IB TO IC IS
C              REVERSED (CMFLIP: OR THE REST OF THE CYCLE, IF SHORTER).
C     IA, IB, IC, ID (INPUT) INTEGER  ENDS; IB BESIDE IA AND ID BESIDE
C                               IC ON THE SAME SIDE, AND THE PATH FROM
C                               IB AWAY FROM IA MEETS IC BEFORE ID
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMMOV2(IA, IB, IC, ID)
      IMPLICIT NONE
      INTEGER IA, IB, IC, ID
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
C     ---- LOCAL -------------------------------------------------------
      INTEGER JA, JL
C
      IF (LTR(MOD(LPS(IA), NLN) + 1) .EQ. IB) THEN
         CALL CMFLIP(LPS(IB), LPS(IC), JA, JL)
      ELSE
         CALL CMFLIP(LPS(IC), LPS(IB), JA, JL)
      END IF
      RETURN
C     END OF CMMOV2
      END
