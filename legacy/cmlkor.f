C=======================================================================
C     CMLKOR - OR-OPT ON THE CYCLE OF ENDS: MOVE ONE TO THREE ENDS
C              ELSEWHERE                                        (SHARED)
C     SOURCE:  I. OR, TRAVELING SALESMAN-TYPE COMBINATORIAL PROBLEMS
C              ..., PH.D. THESIS, NORTHWESTERN UNIVERSITY (1976): THE
C              RUN S OF K ENDS (K = 1, 2, 3) FROM END T1 ON EITHER SIDE
C              IS TAKEN OUT AND PUT BETWEEN TWO NEIGHBOURS X, Y OF THE
C              CYCLE ELSEWHERE, EITHER WAY ROUND, WHEN THAT SHORTENS
C              THE CYCLE. X IS FOUND AMONG THE NEAR ENDS (KNB) OF THE
C              TWO ENDS OF S THAT ARE NEARER TO THEM THAN WHAT TAKING S
C              OUT SAVES. A CHAIN OF 2-OPT MOVES WITH GAIN (CMLKST)
C              CANNOT ALWAYS MAKE SUCH A MOVE; HERE IT IS MADE BY TWO OR
C              THREE 2-OPT MOVES (CMMOV2). S NEVER CUTS AN ITEM, NOR THE
C              MOVE FROM THE TAPE'S END BACK TO ITS START.
C     IT1     (INPUT)  INTEGER  THE END T1
C     LIMP    (OUTPUT) INTEGER  1 IF THE CYCLE WAS SHORTENED, ELSE 0
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMLKOR(IT1, LIMP)
      IMPLICIT NONE
      INTEGER IT1, LIMP
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM)
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI
      SAVE /CMITM/
C     ---- /CMTWJ/ THE JOURNAL OF REVERSALS OF ONE KICK (CMKICK), AND
C     THE LENGTH THE MOVES SINCE THE KICK HAVE TAKEN OFF THE TOUR ------
      INTEGER MXJRN
      PARAMETER (MXJRN = 20000)
      INTEGER NJRN, LJRN, KJRN(2, MXJRN)
      DOUBLE PRECISION DGAIN
      COMMON /CMTWJ/ DGAIN, NJRN, LJRN, KJRN
      SAVE /CMTWJ/
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
      INTEGER ID, K, L, IS1, IS2, IP, INX, IE, NB, IC, IX, IY, IOFF,
     1        ISTEP, IBX, IBY, IBOR, IBD, IBK, IO, I1, I2, IX1, IY1
      DOUBLE PRECISION REM, ADD, GAIN, BEST, DIST
      INTEGER JX1, JY1, JX2, JY2
C     THE DISTANCE OF TWO POINTS: A STATEMENT FUNCTION, NO CALL
      DIST(JX1, JY1, JX2, JY2) = SQRT((DBLE(JX1) - JX2)**2 +
     1   (DBLE(JY1) - JY2)**2)
C
      LIMP = 0
      BEST = 1.0D-6
      IBX = 0
      DO 60 ID = 1, 2
C        ISTEP: +1 WHEN S RUNS FORWARD ALONG THE CYCLE FROM T1
         ISTEP = 1
         IF (ID .EQ. 2) ISTEP = -1
         IS1 = IT1
         I1 = LPS(IT1)
         IP = LTR(MOD(I1 - ISTEP - 1 + NLN, NLN) + 1)
         IF (LMT(IP) .EQ. IS1) GOTO 60
         DO 50 K = 1, 3
            IF (K .GT. NLN - 4) GOTO 60
            I2 = MOD(I1 + ISTEP * (K - 1) - 1 + NLN, NLN) + 1
            IS2 = LTR(I2)
            INX = LTR(MOD(I2 + ISTEP - 1 + NLN, NLN) + 1)
            IF (LMT(IS2) .EQ. INX) GOTO 50
            REM = DIST(KQX(IP), KQY(IP), KQX(IS1), KQY(IS1))
     1          + DIST(KQX(IS2), KQY(IS2), KQX(INX), KQY(INX))
     2          - DIST(KQX(IP), KQY(IP), KQX(INX), KQY(INX))
            IF (REM .LE. BEST) GOTO 50
            DO 40 L = 1, 2
               IE = IS1
               IF (L .EQ. 2) IE = IS2
               DO 30 NB = 1, MXNB
                  IC = KNB(NB, IE)
                  IF (IC .EQ. 0) GOTO 40
                  IF (DIST(KQX(IE), KQY(IE), KQX(IC), KQY(IC)) .GE.
     1                REM - BEST) GOTO 40
C                 NOT IN S
                  IOFF = MOD(ISTEP * (LPS(IC) - I1) + NLN, NLN)
                  IF (IOFF .LT. K) GOTO 30
C                 THE MOVE X-Y IS C AND THE END AFTER IT, OR THE END
C                 BEFORE C AND C (AFTER: ALONG S'S DIRECTION)
                  DO 25 IO = 1, 2
                     IF (IO .EQ. 1) THEN
                        IX = IC
                     ELSE
                        IX = LTR(MOD(LPS(IC) - ISTEP - 1 + NLN, NLN)
     1                       + 1)
                     END IF
                     IY = LTR(MOD(LPS(IX) + ISTEP - 1 + NLN, NLN) + 1)
C                    X AND Y OUTSIDE S, Y NOT THE END BEFORE S, AND X-Y
C                    NOT A FIXED MOVE
                     IOFF = MOD(ISTEP * (LPS(IX) - I1) + NLN, NLN)
                     IF (IOFF .LT. K) GOTO 25
                     IOFF = MOD(ISTEP * (LPS(IY) - I1) + NLN, NLN)
                     IF (IOFF .LT. K) GOTO 25
                     IF (IY .EQ. IP .OR. LMT(IX) .EQ. IY) GOTO 25
C                    (I) X-S2, S1-Y; (II) X-S1, S2-Y
                     ADD = DIST(KQX(IX), KQY(IX), KQX(IS2), KQY(IS2))
     1                   + DIST(KQX(IS1), KQY(IS1), KQX(IY), KQY(IY))
     2                   - DIST(KQX(IX), KQY(IX), KQX(IY), KQY(IY))
                     GAIN = REM - ADD
                     IF (GAIN .GT. BEST) THEN
                        BEST = GAIN
                        IBX = IX
                        IBY = IY
                        IBOR = 1
                        IBD = ID
                        IBK = K
                     END IF
                     ADD = DIST(KQX(IX), KQY(IX), KQX(IS1), KQY(IS1))
     1                   + DIST(KQX(IS2), KQY(IS2), KQX(IY), KQY(IY))
     2                   - DIST(KQX(IX), KQY(IX), KQX(IY), KQY(IY))
                     GAIN = REM - ADD
                     IF (GAIN .GT. BEST) THEN
                        BEST = GAIN
                        IBX = IX
                        IBY = IY
                        IBOR = 2
                        IBD = ID
                        IBK = K
                     END IF
   25             CONTINUE
   30          CONTINUE
   40       CONTINUE
   50    CONTINUE
   60 CONTINUE
      IF (IBX .EQ. 0) RETURN
C     ---- MAKE THE BEST MOVE: S BETWEEN X AND Y -----------------------
      ISTEP = 1
      IF (IBD .EQ. 2) ISTEP = -1
      I1 = LPS(IT1)
      IS1 = IT1
      IP = LTR(MOD(I1 - ISTEP - 1 + NLN, NLN) + 1)
      I2 = MOD(I1 + ISTEP * (IBK - 1) - 1 + NLN, NLN) + 1
      IS2 = LTR(I2)
      INX = LTR(MOD(I2 + ISTEP - 1 + NLN, NLN) + 1)
      IX1 = IBX
      IY1 = IBY
      CALL CMMOV2(IP, IS1, IX1, IY1)
      IF (IX1 .NE. INX) CALL CMMOV2(IP, IX1, INX, IS2)
      IF (IBOR .EQ. 2) CALL CMMOV2(IX1, IS2, IS1, IY1)
      DGAIN = DGAIN + BEST
      LIMP = 1
      CALL CMLQP(IP)
      CALL CMLQP(INX)
      CALL CMLQP(IX1)
      CALL CMLQP(IY1)
      CALL CMLQP(IS1)
      CALL CMLQP(IS2)
      RETURN
C     END OF CMLKOR
      END
