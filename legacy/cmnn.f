C=======================================================================
C     CMNN   - THE LIVE END NEAREST TO A POINT                  (SHARED)
C     SOURCE:  RECONSTRUCTED. THE CELLS ARE SEARCHED IN SQUARE RINGS
C              ROUND THE POINT'S CELL; AFTER RING K NO FARTHER RING CAN
C              HOLD AN END NEARER THAN K CELL WIDTHS.
C     IQX,IQY (INPUT)  INTEGER           THE POINT
C     IB      (OUTPUT) INTEGER           THE NEAREST LIVE END (0: NONE)
C     DB      (OUTPUT) DOUBLE PRECISION  ITS SQUARED DISTANCE
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMNN(IQX, IQY, IB, DB)
      IMPLICIT NONE
      INTEGER IQX, IQY, IB
      DOUBLE PRECISION DB
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
      INTEGER IC, ICX, ICY, K, IGX, IGY, IS, IP, ISTEP, KMAX
      DOUBLE PRECISION D, RK, CMRBND
      EXTERNAL CMRBND
C
      IB = 0
      DB = 1.0D300
      CALL CMCELL(IQX, IQY, IC)
      ICX = MOD(IC - 1, NGX)
      ICY = (IC - 1) / NGX
      KMAX = MAX(NGX, NGY)
      DO 40 K = 0, KMAX
         DO 30 IGY = ICY - K, ICY + K
            IF (IGY .LT. 0 .OR. IGY .GE. NGY) GOTO 30
C           ON THE TOP AND BOTTOM ROW OF THE RING EVERY CELL, ELSE ONLY
C           THE LEFT AND THE RIGHT ONE
            ISTEP = 2 * K
            IF (IGY .EQ. ICY - K .OR. IGY .EQ. ICY + K) ISTEP = 1
            IF (ISTEP .EQ. 0) ISTEP = 1
            DO 20 IGX = ICX - K, ICX + K, ISTEP
               IF (IGX .LT. 0 .OR. IGX .GE. NGX) GOTO 20
               IC = IGX + IGY * NGX + 1
               DO 10 IS = KCST(IC), KCST(IC) + KCCN(IC) - 1
                  IP = KCEL(IS)
                  D = (DBLE(KQX(IP)) - IQX)**2 +
     1                (DBLE(KQY(IP)) - IQY)**2
                  IF (D .LT. DB .OR. (D .EQ. DB .AND. IP .LT. IB)) THEN
                     DB = D
                     IB = IP
                  END IF
   10          CONTINUE
   20       CONTINUE
   30    CONTINUE
         RK = CMRBND(IQX, IQY, ICX, ICY, K)
         IF (RK .GE. 1.0D299) RETURN
         IF (IB .NE. 0 .AND. DB .LE. RK * RK) RETURN
   40 CONTINUE
      RETURN
C     END OF CMNN
      END
