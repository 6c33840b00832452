C=======================================================================
C     CMQPSH - PUT AN ITEM ON THE QUEUE OF ITEMS TO LOOK AT AGAIN
C                                                               (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMOPT2). AN ITEM ALREADY QUEUED IS NOT
C              QUEUED TWICE.
C     M       (INPUT)  INTEGER  THE ITEM, 1..NITM
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMQPSH(M)
      IMPLICIT NONE
      INTEGER M
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
C
      IF (M .LT. 1 .OR. M .GT. NITM) RETURN
      IF (LQUE(M) .EQ. 1) RETURN
      KQUE(MOD(KQHD + KQN - 1, NITM) + 1) = M
      LQUE(M) = 1
      KQN = KQN + 1
      RETURN
C     END OF CMQPSH
      END
