C=======================================================================
C     CMLKST - ONE MOVE OF LIN AND KERNIGHAN FROM AN END        (SHARED)
C     SOURCE:  S. LIN, B. W. KERNIGHAN, AN EFFECTIVE HEURISTIC
C              ALGORITHM FOR THE TRAVELING-SALESMAN PROBLEM, OPERATIONS
C              RESEARCH 21 (1973) 498-516, IN THE FORM OF A CHAIN OF
C              2-OPT MOVES ON THE CYCLE OF ENDS (SEE CMLK).
C              THE MOVE T1-T2 OF THE CYCLE IS TAKEN OUT (T2 BESIDE T1
C              ON EITHER SIDE). STEP I ADDS A MOVE T2-T3 TO ONE OF THE
C              NEAR ENDS T3 OF T2 AND TAKES OUT THE MOVE T3-T4 THAT
C              LETS THE CYCLE CLOSE WITH T4-T1: A REVERSAL OF THE RUN
C              FROM T2 TO T4, AFTER WHICH T4 IS THE T2 OF THE NEXT
C              STEP. A STEP IS TRIED ONLY WHILE WHAT HAS BEEN TAKEN OUT
C              EXCEEDS WHAT HAS BEEN PUT IN (THE GAIN CRITERION), AND A
C              MOVE PUT IN IS NEVER TAKEN OUT AGAIN. THE STEPS BEING
C              TRIED ARE NOT MADE, ONLY LISTED (CMVPOS, CMVEND), SO A
C              STEP COSTS THE CHAIN'S DEPTH, NOT THE RUN'S LENGTH. THE
C              CHAIN GOES ON TO DEPTH MXDEP; THE BEST CLOSED CYCLE ON
C              IT IS MADE (CMFLIP) IF SHORTER THAN THE FIRST. THE NEXT
C              T3 IS CHOSEN BY THE LARGEST D(T3,T4) - D(T2,T3); AT THE
C              FIRST STEP THE BEST MXBR1 ARE TRIED IN TURN, AT THE
C              SECOND MXBR2, DEEPER ONLY THE BEST.
C              A MOVE INSIDE AN ITEM (ITS ENTRY TO ITS EXIT) AND THE
C              MOVE FROM THE TAPE'S END BACK TO ITS START ARE NEVER
C              TAKEN OUT.
C     IT1     (INPUT)  INTEGER  THE END T1
C     LIMP    (OUTPUT) INTEGER  1 IF THE CYCLE WAS SHORTENED, ELSE 0
C     THE GAIN IS ADDED TO DGAIN; THE ENDS OF THE MOVES CHANGED ARE
C     QUEUED (CMLQP). ONLY THE REVERSALS MADE GO INTO THE JOURNAL.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMLKST(IT1, LIMP)
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
C     ---- /CMTLV/ THE REVERSALS OF A MOVE BEING TRIED (CMLKST) --------
      INTEGER MXDEP
      PARAMETER (MXDEP = 3)
      INTEGER NVR, KRA(MXDEP), KRB(MXDEP)
      COMMON /CMTLV/ NVR, KRA, KRB
      SAVE /CMTLV/
C     ---- LOCAL -------------------------------------------------------
      INTEGER MXBR1, MXBR2
      PARAMETER (MXBR1 = 3, MXBR2 = 1)
      INTEGER KT2(MXDEP), KT3(MXDEP), KT4(MXDEP), NC(MXDEP), IC(MXDEP),
     1        KC3(MXBR1, MXDEP), KC4(MXBR1, MXDEP)
      DOUBLE PRECISION GO(MXDEP), SC(MXBR1)
      INTEGER ID, IDIR, IT2, IT3, IT4, L, LL, LBEST, K, J, NB, IP, IQ,
     1        IA, LEN, CMVPOS, CMVEND
      EXTERNAL CMVPOS, CMVEND
      DOUBLE PRECISION BEST, G1, CLOSE, S, DIST
      INTEGER JX1, JY1, JX2, JY2
C     THE DISTANCE OF TWO POINTS: A STATEMENT FUNCTION, NO CALL
      DIST(JX1, JY1, JX2, JY2) = SQRT((DBLE(JX1) - JX2)**2 +
     1   (DBLE(JY1) - JY2)**2)
C
      LIMP = 0
      NVR = 0
      DO 90 ID = 1, 2
C        IDIR = 1: T2 FOLLOWS T1 ON THE CYCLE; 2: T2 PRECEDES IT
         IDIR = ID
         IP = LPS(IT1)
         IF (IDIR .EQ. 1) THEN
            IT2 = LTR(MOD(IP, NLN) + 1)
         ELSE
            IT2 = LTR(MOD(IP - 2 + NLN, NLN) + 1)
         END IF
         IF (LMT(IT1) .EQ. IT2) GOTO 90
         L = 1
         KT2(1) = IT2
         GO(1) = DIST(KQX(IT1), KQY(IT1), KQX(IT2), KQY(IT2))
         BEST = 1.0D-6
         LBEST = 0
         GOTO 60
C        ---- THE NEXT CANDIDATE OF STEP L -----------------------------
   20    CONTINUE
         IC(L) = IC(L) + 1
         IF (IC(L) .GT. NC(L)) THEN
            IF (L .EQ. 1) GOTO 90
C           BACK TO THE STEP BEFORE: ITS REVERSAL IS STRUCK OFF
            L = L - 1
            NVR = L - 1
            GOTO 25
         END IF
         IT3 = KC3(IC(L), L)
         IT4 = KC4(IC(L), L)
C        ---- LIST THE REVERSAL OF THE RUN T2..T4 ----------------------
         IP = CMVPOS(KT2(L))
         IQ = CMVPOS(IT4)
         NVR = L
         IF (IDIR .EQ. 1) THEN
            KRA(L) = IP
            KRB(L) = IQ
         ELSE
            KRA(L) = IQ
            KRB(L) = IP
         END IF
         KT3(L) = IT3
         KT4(L) = IT4
         G1 = GO(L) - DIST(KQX(KT2(L)), KQY(KT2(L)), KQX(IT3),
     1                     KQY(IT3))
         CLOSE = G1 + DIST(KQX(IT3), KQY(IT3), KQX(IT4), KQY(IT4))
     1              - DIST(KQX(IT4), KQY(IT4), KQX(IT1), KQY(IT1))
         IF (CLOSE .GT. BEST) THEN
            BEST = CLOSE
            LBEST = L
         END IF
         IF (L .EQ. MXDEP) GOTO 70
         L = L + 1
         KT2(L) = IT4
         GO(L) = G1 + DIST(KQX(IT3), KQY(IT3), KQX(IT4), KQY(IT4))
         IC(L) = 0
   25    CONTINUE
C        THE SIDE OF T1 ON WHICH T2 NOW LIES
         IF (CMVEND(MOD(CMVPOS(IT1), NLN) + 1) .EQ. KT2(L)) THEN
            IDIR = 1
         ELSE
            IDIR = 2
         END IF
         IF (IC(L) .GT. 0) GOTO 20
C        ---- THE CANDIDATES T3 OF STEP L, BEST FIRST ------------------
   60    CONTINUE
         NB = 1
         IF (L .EQ. 1) NB = MXBR1
         IF (L .EQ. 2) NB = MXBR2
         NC(L) = 0
         IC(L) = 0
         IT2 = KT2(L)
         DO 50 K = 1, MXNB
            IT3 = KNB(K, IT2)
            IF (IT3 .EQ. 0) GOTO 55
            G1 = GO(L) - DIST(KQX(IT2), KQY(IT2), KQX(IT3), KQY(IT3))
            IF (G1 .LE. 1.0D-6) GOTO 55
            IF (IT3 .EQ. IT1) GOTO 50
            IP = CMVPOS(IT3)
            IF (IDIR .EQ. 1) THEN
               IT4 = CMVEND(MOD(IP - 2 + NLN, NLN) + 1)
            ELSE
               IT4 = CMVEND(MOD(IP, NLN) + 1)
            END IF
            IF (IT4 .EQ. IT2 .OR. LMT(IT3) .EQ. IT4) GOTO 50
C           NOT A MOVE THIS CHAIN PUT IN
            DO 40 LL = 1, L - 1
               IF ((KT2(LL) .EQ. IT3 .AND. KT3(LL) .EQ. IT4) .OR.
     1             (KT2(LL) .EQ. IT4 .AND. KT3(LL) .EQ. IT3)) GOTO 50
   40       CONTINUE
            S = DIST(KQX(IT3), KQY(IT3), KQX(IT4), KQY(IT4))
     1          - DIST(KQX(IT2), KQY(IT2), KQX(IT3), KQY(IT3))
C           INTO THE LIST OF THE NB BEST, KEPT IN ORDER (TIES: THE
C           NEARER T3 FIRST, AS FOUND)
            J = NC(L)
            IF (J .EQ. NB) THEN
               IF (S .LE. SC(NB)) GOTO 50
               J = NB - 1
            END IF
   45       CONTINUE
            IF (J .GE. 1) THEN
               IF (SC(J) .LT. S) THEN
                  SC(J + 1) = SC(J)
                  KC3(J + 1, L) = KC3(J, L)
                  KC4(J + 1, L) = KC4(J, L)
                  J = J - 1
                  GOTO 45
               END IF
            END IF
            SC(J + 1) = S
            KC3(J + 1, L) = IT3
            KC4(J + 1, L) = IT4
            NC(L) = MIN(NC(L) + 1, NB)
   50    CONTINUE
   55    CONTINUE
         IF (NC(L) .GT. 0) GOTO 20
C        ---- NO STEP FROM HERE: THE CHAIN ENDS AT STEP L-1 ------------
         L = L - 1
         IF (L .EQ. 0) GOTO 90
   70    CONTINUE
         IF (LBEST .GT. 0) THEN
C           MAKE THE CHAIN'S STEPS UP TO ITS BEST CYCLE
            NVR = 0
            DO 75 LL = 1, LBEST
               IP = LPS(IT1)
               IF (LTR(MOD(IP, NLN) + 1) .EQ. KT2(LL)) THEN
                  CALL CMFLIP(LPS(KT2(LL)), LPS(KT4(LL)), IA, LEN)
               ELSE
                  CALL CMFLIP(LPS(KT4(LL)), LPS(KT2(LL)), IA, LEN)
               END IF
   75       CONTINUE
            DGAIN = DGAIN + BEST
            LIMP = 1
            CALL CMLQP(IT1)
            DO 80 LL = 1, LBEST
               CALL CMLQP(KT2(LL))
               CALL CMLQP(KT3(LL))
               CALL CMLQP(KT4(LL))
   80       CONTINUE
            RETURN
         END IF
C        NO GAIN ON THIS CHAIN: STRIKE OFF ITS LAST STEP, TRY THE NEXT
         NVR = L - 1
         GOTO 25
   90 CONTINUE
      NVR = 0
      RETURN
C     END OF CMLKST
      END
