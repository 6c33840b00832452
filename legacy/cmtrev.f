C=======================================================================
C     CMTREV - REVERSE THE TOUR BETWEEN TWO PLACES              (SHARED)
C     SOURCE:  RECONSTRUCTED. THE ITEMS AT PLACES I1..I2 ARE PUT IN
C              REVERSE ORDER AND EACH IS TURNED TO BE DRAWN THE OTHER
C              WAY.
C     I1, I2  (INPUT)  INTEGER  THE PLACES, 1 .LE. I1, I2 .LE. NITM;
C                               NOTHING IS DONE WHEN I1 .GT. I2
C     THE WORK DONE (ITEMS MOVED) IS COUNTED IN KWORK.
C     CHANGES: 2026-11-22 FIRST RECONSTRUCTION
C=======================================================================
      SUBROUTINE CMTREV(I1, I2)
      IMPLICIT NONE
      INTEGER I1, I2
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM)
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI
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
C     ---- LOCAL -------------------------------------------------------
      INTEGER I, J, M
C
      I = I1
      J = I2
   10 CONTINUE
      IF (I .LT. J) THEN
         M = ITOUR(I)
         ITOUR(I) = ITOUR(J)
         ITOUR(J) = M
         I = I + 1
         J = J - 1
         GOTO 10
      END IF
      DO 20 I = I1, I2
         M = ITOUR(I)
         IPOS(M) = I
         IORI(M) = 1 - IORI(M)
   20 CONTINUE
      KWORK = KWORK + MAX(0, I2 - I1 + 1)
      RETURN
C     END OF CMTREV
      END
