C=======================================================================
C     CMOR3  - OR-3OPT: MOVE A RUN OF ITEMS OF ANY LENGTH ELSEWHERE
C                                                               (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMTOUR). THE RUN S STARTS AT ITEM M
C              AND ENDS AT THE ITEM AT PLACE J2 .GE. IPOS(M); IT IS
C              TAKEN OUT AND PUT BETWEEN THE ITEMS AT PLACES C AND C+1,
C              DRAWN FORWARD OR BACKWARD. THREE MOVES GO OUT (INTO S,
C              OUT OF S, C TO C+1) AND THREE COME IN, FOUND AS LIN AND
C              KERNIGHAN'S SEQUENTIAL 3-OPT STEP IS: THE START OF S IS
C              JOINED TO A NEAR END T3 (KNB), NEARER THAN ITS MOVE IN;
C              T3 IS AN END OF C OR OF C+1, AND THE OTHER ONE, T4, IS
C              JOINED TO A NEAR END T5 OF ITS OWN, WHICH BECOMES THE END
C              OF S, AS LONG AS THE SUM OF WHAT IS TAKEN OUT LESS WHAT
C              IS PUT IN STAYS ABOVE NOTHING. CMOROP TRIES RUNS OF ONE
C              TO THREE ITEMS ONLY; THIS ONE FINDS LONG RUNS, SUCH AS A
C              ROW OF PADS DRAWN IN THE WRONG PLACE, IN ONE MOVE. S RUNS
C              FORWARD FROM M, THEN BACK FROM IT (T2 THEN THE END M IS
C              LEFT BY). THE BEST MOVE FOUND IS MADE BY CMRUNM, AS
C              IN CMOROP.
C     M       (INPUT)  INTEGER  THE FIRST ITEM OF THE RUN
C     LIMP    (OUTPUT) INTEGER  1 IF THE TOUR WAS CHANGED, ELSE 0
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMOR3(M, LIMP)
      IMPLICIT NONE
      INTEGER M, LIMP
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
C     ---- /CMTWD/ THE LENGTH FROM EACH END TO EACH OF ITS NEAR ENDS --
      DOUBLE PRECISION DNB(MXNB, MXPT)
      COMMON /CMTWD/ DNB
      SAVE /CMTWD/
C     ---- /CMTWJ/ WHAT A KICK (CMKICK) HAS CHANGED, TO PUT IT BACK, AND
C     THE LENGTH THE MOVES SINCE THE KICK HAVE TAKEN OFF THE TOUR ------
      INTEGER MXJRN
      PARAMETER (MXJRN = 20000)
      INTEGER NJRN, LJRN, KJWK, KJLO, KJHI, KJIT(MXITM), KJOR(MXITM)
      DOUBLE PRECISION DGAIN
      COMMON /CMTWJ/ DGAIN, NJRN, LJRN, KJWK, KJLO, KJHI, KJIT, KJOR
      SAVE /CMTWJ/
C     ---- /CMTWM/ THE LENGTH OF EACH END'S MOVE (CMDMV), AND THE OLD
C     LENGTHS A KICK HAS CHANGED: NDJ PAIRS, THE END KDJE(J) AND THE
C     LENGTH DDJV(J) IT HAD (TWO PAIRS A MOVE, AT MOST TWO MOVES A
C     REVERSAL, AT MOST MXJRN REVERSALS A KICK) -----------------------
      INTEGER MXDJ
      PARAMETER (MXDJ = 4 * MXJRN + 16)
      INTEGER NDJ, KDJE(MXDJ)
      DOUBLE PRECISION DMV(MXPT + 2), DDJV(MXDJ)
      COMMON /CMTWM/ DMV, DDJV, NDJ, KDJE
      SAVE /CMTWM/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I, J, J2, L, IC, IREV, NB, NB5, IBC, IBS, IBE, IBREV,
     1        IQ, M2, IDIR, IE2, IE4, IE5, IES, IQ4, M5, IXP, IYP, IXN,
     2        IYN, IROLE, MS(6)
      LOGICAL LEXIT, LONE
      DOUBLE PRECISION DPS, G1, G2, GAIN, BEST, DCD, DIST
      INTEGER JX1, JY1, JX2, JY2
      INTEGER KIN, KOUT, MM
C     THE DISTANCE OF TWO POINTS: A STATEMENT FUNCTION, NO CALL
      DIST(JX1, JY1, JX2, JY2) = SQRT((DBLE(JX1) - JX2)**2 +
     1   (DBLE(JY1) - JY2)**2)
C     THE END ITEM MM IS ENTERED BY, AND THE END IT IS LEFT BY, AS IT
C     IS DRAWN NOW (CMEND'S RULE)
      KIN(MM) = 2 * MM - 1 + IORI(MM)
      KOUT(MM) = 2 * MM - IORI(MM)
C
      LIMP = 0
      I = IPOS(M)
      BEST = 1.0D-6
      IBC = -1
      IBS = 0
      IBE = 0
      IBREV = 0
C     IDIR 1: S RUNS FORWARD FROM M (T2 THE END M IS ENTERED BY, T1 THE
C     END BEFORE IT); IDIR 2: S RUNS BACK FROM M (T2 THE END M IS LEFT
C     BY, T1 THE END AFTER IT)
      DO 50 IDIR = 1, 2
      IF (IDIR .EQ. 1) THEN
         IE2 = KIN(M)
         IF (I .GT. 1) THEN
            IE4 = KOUT(ITOUR(I - 1))
            IXP = KQX(IE4)
            IYP = KQY(IE4)
         ELSE
            IXP = KDSX
            IYP = KDSY
         END IF
      ELSE
         IE2 = KOUT(M)
         IF (I .LT. NITM) THEN
            IE4 = KIN(ITOUR(I + 1))
            IXP = KQX(IE4)
            IYP = KQY(IE4)
         ELSE
            IXP = KDTX
            IYP = KDTY
         END IF
      END IF
C     THE MOVE INTO S, AS ALL MOVES TAKEN OUT HERE, FROM DMV (CMDMV)
      DPS = DMV(IE2)
C     ---- T3: A NEAR END OF T2, NEARER THAN T1 ------------------------
      DO 40 NB = 1, MXNB
         IQ = KNB(NB, IE2)
         IF (IQ .EQ. 0) GOTO 50
         G1 = DPS - DNB(NB, IE2)
         IF (G1 .LE. 1.0D-6) GOTO 50
         M2 = (IQ + 1) / 2
         J = IPOS(M2)
         LEXIT = IQ .EQ. KOUT(M2)
         LONE = KQX(2*M2) .EQ. KQX(2*M2-1) .AND.
     1          KQY(2*M2) .EQ. KQY(2*M2-1)
         IROLE = 0
C        T3 THE END OF C OR THE START OF C+1; S IS DRAWN FORWARD WHEN
C        IT JOINS T3 BY THE END IT IS JOINED BY NOW (THE START OF S TO
C        THE END OF C, OR THE END OF S TO THE START OF C+1). AN ITEM
C        WHOSE ENDS ARE ONE POINT IS TRIED IN BOTH ROLES.
   25    CONTINUE
         IF (LONE) LEXIT = IROLE .EQ. 0
         IF (LEXIT) THEN
            IC = J
         ELSE
            IC = J - 1
         END IF
         IREV = 0
         IF ((IDIR .EQ. 1) .NEQV. LEXIT) IREV = 1
         IF (IC .GE. I - 1 .AND. IC .LE. I) GOTO 38
C        C AND D, THE ENDS AT PLACES C AND C+1; T4 THE ONE NOT T3, AND
C        THE LENGTH OF THEIR MOVE (DMV, CMDMV)
         IF (LEXIT) THEN
            IF (IC .GE. NITM) GOTO 38
            IQ4 = KIN(ITOUR(IC + 1))
         ELSE
            IF (IC .LT. 1) GOTO 38
            IQ4 = KOUT(ITOUR(IC))
         END IF
         DCD = DMV(IQ4)
C        ---- T5: A NEAR END OF T4, THE OTHER END OF S -----------------
         DO 30 NB5 = 1, MXNB
            IE5 = KNB(NB5, IQ4)
            IF (IE5 .EQ. 0) GOTO 38
            G2 = G1 + DCD - DNB(NB5, IQ4)
            IF (G2 .LE. 1.0D-6) GOTO 38
            M5 = (IE5 + 1) / 2
            J2 = IPOS(M5)
C           T5 MUST BE THE END S IS LEFT BY (IDIR 1) OR ENTERED BY
C           (IDIR 2), AND S MUST NOT HOLD C OR C+1
            IF (IDIR .EQ. 1) THEN
               IE4 = KOUT(M5)
            ELSE
               IE4 = KIN(M5)
            END IF
C           (IES: THAT END, WHOSE MOVE IS THE ONE TAKEN OUT AFTER S; AN
C           ITEM WHOSE ENDS ARE ONE POINT MAY BE OFFERED BY THE OTHER)
            IES = IE4
            IF (IE5 .NE. IE4) THEN
               IF (KQX(2*M5) .NE. KQX(2*M5-1) .OR.
     1             KQY(2*M5) .NE. KQY(2*M5-1)) GOTO 30
            END IF
            IF (IDIR .EQ. 1) THEN
               IF (J2 .LT. I) GOTO 30
               IF (IC .GT. I .AND. J2 .GE. IC) GOTO 30
C              T6, THE START OF THE ITEM AFTER S, IS JOINED TO T1
               IF (J2 .LT. NITM) THEN
                  IE4 = KIN(ITOUR(J2 + 1))
                  IXN = KQX(IE4)
                  IYN = KQY(IE4)
               ELSE
                  IXN = KDTX
                  IYN = KDTY
               END IF
            ELSE
               IF (J2 .GT. I) GOTO 30
               IF (IC .LT. I .AND. J2 .LE. IC + 1) GOTO 30
C              T6, THE END OF THE ITEM BEFORE S, IS JOINED TO T1
               IF (J2 .GT. 1) THEN
                  IE4 = KOUT(ITOUR(J2 - 1))
                  IXN = KQX(IE4)
                  IYN = KQY(IE4)
               ELSE
                  IXN = KDSX
                  IYN = KDSY
               END IF
            END IF
            GAIN = G2 + DMV(IES)
     1           - DIST(IXP, IYP, IXN, IYN)
            IF (GAIN .GT. BEST) THEN
               BEST = GAIN
               IBC = IC
               IBS = MIN(I, J2)
               IBE = MAX(I, J2)
               IBREV = IREV
            END IF
   30    CONTINUE
   38    CONTINUE
         IROLE = IROLE + 1
         IF (LONE .AND. IROLE .EQ. 1) GOTO 25
   40 CONTINUE
   50 CONTINUE
      IF (IBC .LT. 0) RETURN
C     ---- MAKE THE MOVE; QUEUE THE ITEMS WHOSE NEIGHBOURS CHANGE ------
      I = IBS
      J2 = IBE
      DO 55 L = 1, 6
         MS(L) = 0
   55 CONTINUE
      IF (I .GT. 1) MS(1) = ITOUR(I - 1)
      IF (J2 .LT. NITM) MS(2) = ITOUR(J2 + 1)
      IF (IBC .GE. 1) MS(3) = ITOUR(IBC)
      IF (IBC .LT. NITM) MS(4) = ITOUR(IBC + 1)
      MS(5) = ITOUR(I)
      MS(6) = ITOUR(J2)
      CALL CMRUNM(I, J2, IBC, IBREV)
      DO 60 L = 1, 6
         IF (MS(L) .NE. 0) CALL CMQPSH(MS(L))
   60 CONTINUE
      DGAIN = DGAIN + BEST
      LIMP = 1
      RETURN
C     END OF CMOR3
      END
