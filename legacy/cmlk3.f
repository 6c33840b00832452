C=======================================================================
C     CMLK3  - LIN AND KERNIGHAN'S CHAIN OF 3-OPT MOVES         (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMTOUR), AS HELSGAUN'S LKH MAKES ITS
C              MOVE OF TYPE 3 (DOCS/SOURCES.MD). THE TOUR IS SEEN AS A
C              CYCLE OF ENDS: PLACE 0 THE TOOL'S START, 2P-1 AND 2P THE
C              ENTRY AND EXIT OF THE ITEM AT TOUR PLACE P, 2*NITM+1 THE
C              START POINT, AND BACK TO PLACE 0. PLACES 2B AND 2B+1 ARE
C              JOINED BY A MOVE (THE MOVE AFTER TOUR PLACE B); THE MOVE
C              INSIDE AN ITEM AND THE ONE FROM THE START POINT BACK TO
C              THE TOOL'S START ARE FIXED. T1 IS AN END OF ITEM M AND T2
C              THE END ACROSS ITS MOVE. A STEP TAKES OUT THE MOVES
C              T1-T2, T3-T4 AND T5-T6 AND PUTS IN T2-T3, T4-T5 AND
C              T6-T1: T3 IS ONE OF THE NBRD NEAREST ENDS OF T2 (KNB;
C              BOTH ENDS OF AN ITEM WHOSE ENDS ARE ONE POINT) AND T5 ONE
C              OF T4, EACH NEARER THAN WHAT THE CHAIN HAS GAINED SO FAR
C              (THE GAIN CRITERION), AND T4, T6 ARE THE ENDS ACROSS
C              THEIR MOVES. A 2-OPT MOVE (T4-T1 PUT IN) OR 3-OPT MOVE
C              THAT SHORTENS THE TOUR IS MADE AT ONCE AND ENDS THE
C              CHAIN. ELSE THE STEP WHOSE GAIN BEFORE T6-T1 IS GREATEST
C              IS MADE, IF IT STAYS ABOVE THE LENGTH FROM T6 TO ITS
C              NEAREST END AND ITS T5-T6 IS A MOVE THE CHAIN HAS NOT
C              TOUCHED, AND THE CHAIN GOES ON FROM T1 AND T6 (AT MOST
C              MXDEP STEPS). A CHAIN THAT ENDS WITHOUT A SHORTER TOUR IS
C              UNDONE, ITS REVERSALS REVERSED LAST FIRST. WHETHER SIX
C              ENDS MAKE A TOUR IS FOUND AS LKH FINDS IT, FROM THEIR
C              PLACES COUNTED FROM T1 TOWARDS T2. AN EARLIER TRIAL
C              FORBADE EVERY END THE CHAIN HAD TOUCHED AS T3 OR T5; ITS
C              TOURS WERE TWICE AS FAR FROM THE OPTIMUM
C              (DOCS/PERFORMANCE.MD). THE BREADTH NBRD IS 8 NEAR ENDS,
C              AND 16 ON A TAPE OF MORE THAN 2000 ITEMS: ON TSPLIB'S
C              D2103 AND PCB3038, EIGHT DECKS OF EACH (AS PUBLISHED,
C              MIRRORED, SIX ORDERS OF THE PADS), 15 TOURS OF 16 THEN
C              CAME WITHIN 1 PER CENT OF THE OPTIMUM, AGAINST 11. ON
C              SMALLER TAPES 16 COST D198 AND D657 TWICE THE TIME OF
C              THEIR FIRST TOUR, AND LEFT ONE OF FL1400'S EIGHT DECKS
C              (1400 ITEMS) 4.2 PER CENT OVER, AGAINST 0.2.
C     M       (INPUT)  INTEGER  THE ITEM WHOSE TWO ENDS ARE TRIED AS T1
C     LIMP    (OUTPUT) INTEGER  1 IF THE TOUR WAS CHANGED, ELSE 0
C     THE LENGTH TAKEN OFF IS ADDED TO DGAIN; EACH T3 AND T5 LOOKED AT
C     ADDS 1 TO THE WORK KWORK, EACH ITEM A REVERSAL MOVES 1 (CMTREV).
C     T1-T2, T3-T4 AND T5-T6 ARE MOVES OF THE TOUR: THEIR LENGTHS ARE
C     READ FROM DMV (CMDMV), THE SAME TO THE LAST BIT AS THEIR ROOTS.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMLK3(M, LIMP)
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
C     ---- /CMTWE/ THE NEAR ENDS OF THE TOOL'S START (1) AND OF THE
C     START POINT (2), AND THEIR LENGTHS ------------------------------
      INTEGER KENB(MXNB, 2), NENB(2)
      DOUBLE PRECISION DENB(MXNB, 2)
      COMMON /CMTWE/ DENB, KENB, NENB
      SAVE /CMTWE/
C     ---- /CMTWL/ THE CHAIN OF CMLK3 THAT LAST CHANGED EACH END'S
C     MOVE (ITS NUMBER ICHN) -------------------------------------------
      INTEGER ICHN, KADD(MXPT + 2)
      COMMON /CMTWL/ ICHN, KADD
      SAVE /CMTWL/
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
      INTEGER MXDEP, MXREV
      PARAMETER (MXDEP = 50, MXREV = 3 * MXDEP)
      INTEGER KR1(MXREV), KR2(MXREV), NREV, KTCH(4 * MXDEP + 5), NTCH,
     1        ISIDE, NP2, NCY, NDEP, IDR, NEV, IT1, IT2, IT3, IT4, IT5,
     2        IT6, IP1, IP2, IP3, IP4, IP5, IP6, IB1, IB3, IB5, IR3P,
     3        IR4P, IR5P, IR6P, K3, K5, IR, NR3, NR5, M3, M5, MM2, IQ3,
     4        IQ5, IX1, IY1, IX4, IY4, IX6, IY6,
     5        ITYP, IBA, IBB, IBC, JB3, JB4, JB5, JB6, JTYP, JBA, JBB,
     6        JBC, L, I, NBRD
      LOGICAL L2OPT
      DOUBLE PRECISION G0, G1, G2, G3, G4, GAIN, BESTG, D23, D45, DNR,
     1        D51, DIST
      INTEGER CMLPS, CMLED
      EXTERNAL CMLPS, CMLED
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
C     THE BREADTH: 8 NEAR ENDS, 16 ON A TAPE OF MORE THAN 2000 ITEMS
      NBRD = 8
      IF (NITM .GT. 2000) NBRD = 16
      NP2 = 2 * NITM
      NCY = NP2 + 2
      DO 900 ISIDE = 1, 2
      IF (ISIDE .EQ. 1) THEN
         IT1 = KOUT(M)
      ELSE
         IT1 = KIN(M)
      END IF
      ICHN = ICHN + 1
      NREV = 0
      NTCH = 0
      IP1 = CMLPS(IT1)
C     T2 IS ACROSS THE MOVE: PLACES 2B AND 2B+1 ARE ONE MOVE'S ENDS
      IP2 = 4 * (IP1 / 2) + 1 - IP1
      IT2 = CMLED(IP2)
      IX1 = KQX(IT1)
      IY1 = KQY(IT1)
      G0 = DMV(IT1)
      NDEP = 0
C     ---- ONE STEP: THE BEST T3..T6 FOR T1, T2 AND THE GAIN G0 --------
  100 CONTINUE
      NDEP = NDEP + 1
      NEV = 0
C     THE PLACE JP COUNTED FROM T1 TOWARDS T2 IS (JP - IP1) * IDR,
C     PLUS NCY IF BELOW 0
      IDR = IP2 - IP1
      IB1 = IP1 / 2
      BESTG = -1.0D30
      JB6 = 0
      DO 300 K3 = 1, NBRD
         IF (IT2 .LE. NP2) THEN
            IQ3 = KNB(K3, IT2)
            D23 = DNB(K3, IT2)
         ELSE
            IF (K3 .GT. NENB(IT2 - NP2)) GOTO 310
            IQ3 = KENB(K3, IT2 - NP2)
            D23 = DENB(K3, IT2 - NP2)
         END IF
         IF (IQ3 .EQ. 0) GOTO 310
         G1 = G0 - D23
C        THE NEAR ENDS COME NEAREST FIRST: NO FURTHER ONE CAN GAIN
         IF (G1 .LE. 1.0D-6) GOTO 310
         M3 = (IQ3 + 1) / 2
         NR3 = 1
         IF (KQX(2*M3) .EQ. KQX(2*M3-1) .AND.
     1       KQY(2*M3) .EQ. KQY(2*M3-1)) NR3 = 2
         DO 290 IR = 1, NR3
         NEV = NEV + 1
         IT3 = IQ3
         IF (NR3 .EQ. 2) IT3 = 2 * M3 - 2 + IR
C        THE PLACE OF T3: 2P-1 IF IT IS THE END M3 IS ENTERED BY, ELSE
C        2P (CMLPS WRITTEN OUT)
         IP3 = 2 * IPOS(M3) - 1 + ABS(IT3 - 2 * M3 + 1 - IORI(M3))
         IB3 = IP3 / 2
         IF (IB3 .EQ. IB1) GOTO 290
         IP4 = 4 * IB3 + 1 - IP3
         IR3P = (IP3 - IP1) * IDR
         IF (IR3P .LT. 0) IR3P = IR3P + NCY
         IR4P = (IP4 - IP1) * IDR
         IF (IR4P .LT. 0) IR4P = IR4P + NCY
         IT4 = CMLED(IP4)
         CALL CMLXY(IT4, IX4, IY4)
         G2 = G1 + DMV(IT3)
C        ---- T4 JUST BEFORE T3: THE 2-OPT MOVE THAT PUTS IN T4-T1 -----
         L2OPT = IR4P .EQ. IR3P - 1
         IF (L2OPT) THEN
            GAIN = G2 - DIST(IX4, IY4, IX1, IY1)
            IF (GAIN .GT. 1.0D-6) THEN
               CALL CMLMV(5, MIN(IB1, IB3), MAX(IB1, IB3), 0, KR1,
     1                    KR2, NREV)
               KTCH(NTCH + 1) = IT2
               KTCH(NTCH + 2) = IT3
               KTCH(NTCH + 3) = IT4
               NTCH = NTCH + 3
               GOTO 800
            END IF
         END IF
C        ---- T5 A NEAR END OF T4, T6 ACROSS ITS MOVE -----------------
         DO 280 K5 = 1, NBRD
            IF (IT4 .LE. NP2) THEN
               IQ5 = KNB(K5, IT4)
               D45 = DNB(K5, IT4)
            ELSE
               IF (K5 .GT. NENB(IT4 - NP2)) GOTO 290
               IQ5 = KENB(K5, IT4 - NP2)
               D45 = DENB(K5, IT4 - NP2)
            END IF
            IF (IQ5 .EQ. 0) GOTO 290
            G3 = G2 - D45
            IF (G3 .LE. 1.0D-6) GOTO 290
            M5 = (IQ5 + 1) / 2
            NR5 = 1
            IF (KQX(2*M5) .EQ. KQX(2*M5-1) .AND.
     1          KQY(2*M5) .EQ. KQY(2*M5-1)) NR5 = 2
            DO 270 L = 1, NR5
            NEV = NEV + 1
            IT5 = IQ5
            IF (NR5 .EQ. 2) IT5 = 2 * M5 - 2 + L
C           T6 IS ACROSS THE MOVE OF T5, WHOSE LENGTH IS DMV(T5), SO
C           T6-T1 IS AT LEAST T5-T1 LESS DMV(T5). THE STEP CAN CLOSE
C           SHORTER ONLY IF T5-T1 IS SHORTER THAN G4 + DMV(T5), AND BE
C           THE BEST SO FAR ONLY IF G4 IS ABOVE BESTG: A T5 THAT CAN DO
C           NEITHER IS PASSED BY BEFORE ITS PLACE IS LOOKED UP (TWO IN
C           THREE TO NEARLY THREE IN FOUR ON TSPLIB'S DRILLING BOARDS).
C           THE SAME STEPS ARE MADE, AND EACH T5 IS STILL COUNTED IN THE
C           WORK; THE 1.0D-6 MORE KEEPS ROUNDING ON THE SAFE SIDE.
            G4 = G3 + DMV(IT5)
            IF (G4 .LE. BESTG) THEN
               D51 = G4 + DMV(IT5) + 1.0D-6
               IF ((DBLE(KQX(IT5)) - IX1)**2 + (DBLE(KQY(IT5)) - IY1)**2
     1             .GE. D51**2) GOTO 270
            END IF
            IP5 = 2 * IPOS(M5) - 1 + ABS(IT5 - 2 * M5 + 1 - IORI(M5))
            IB5 = IP5 / 2
            IF (IB5 .EQ. IB1 .OR. IB5 .EQ. IB3) GOTO 270
            IP6 = 4 * IB5 + 1 - IP5
C           THE SIX ENDS MAKE A TOUR ONLY SO (LKH): WITH T4 JUST BEFORE
C           T3, T6 MUST COME AFTER T5 IF T5 LIES BETWEEN T2 AND T4, ELSE
C           BEFORE IT; WITH T4 AFTER T3, T5 MUST LIE BETWEEN T2 AND T3
            IR5P = (IP5 - IP1) * IDR
            IF (IR5P .LT. 0) IR5P = IR5P + NCY
            IR6P = (IP6 - IP1) * IDR
            IF (IR6P .LT. 0) IR6P = IR6P + NCY
            IF (L2OPT) THEN
               IF (IR5P .LE. IR4P) THEN
                  IF (IR6P .NE. IR5P + 1) GOTO 270
               ELSE
                  IF (IR6P .NE. IR5P - 1) GOTO 270
               END IF
            ELSE
               IF (IR5P .GT. IR3P .OR. IR6P .EQ. 0) GOTO 270
            END IF
C           T6 (CMLED AND CMLXY WRITTEN OUT: THE INNERMOST LOOP)
            IF (IP6 .EQ. 0) THEN
               IT6 = NP2 + 1
               IX6 = KDSX
               IY6 = KDSY
            ELSE IF (IP6 .EQ. NP2 + 1) THEN
               IT6 = NP2 + 2
               IX6 = KDTX
               IY6 = KDTY
            ELSE
               MM2 = ITOUR((IP6 + 1) / 2)
               IF (MOD(IP6, 2) .EQ. 1) THEN
                  IT6 = KIN(MM2)
               ELSE
                  IT6 = KOUT(MM2)
               END IF
               IX6 = KQX(IT6)
               IY6 = KQY(IT6)
            END IF
C           THE STEP CLOSES SHORTER IF T6-T1 IS SHORTER THAN G4: THE
C           SQUARES FIRST, THE ROOT ONLY THEN
            GAIN = 0.0D0
            IF (G4 .GT. 1.0D-6) THEN
               IF ((DBLE(IX6) - IX1)**2 + (DBLE(IY6) - IY1)**2
     1             .LT. (G4 - 1.0D-6)**2)
     2            GAIN = G4 - DIST(IX6, IY6, IX1, IY1)
            END IF
            IF (GAIN .GT. 1.0D-6) THEN
               CALL CMLCL3(IP1, IP2, IP3, IP4, IP5, IP6, ITYP,
     1                     IBA, IBB, IBC)
               IF (ITYP .EQ. 0) GOTO 270
               CALL CMLMV(ITYP, IBA, IBB, IBC, KR1, KR2, NREV)
               KTCH(NTCH + 1) = IT2
               KTCH(NTCH + 2) = IT3
               KTCH(NTCH + 3) = IT4
               KTCH(NTCH + 4) = IT5
               KTCH(NTCH + 5) = IT6
               NTCH = NTCH + 5
               GOTO 800
            END IF
C           THE BEST STEP THAT DOES NOT CLOSE SO FAR: G4 ABOVE WHAT T6
C           NEEDS TO REACH ITS NEAREST END, T5-T6 UNTOUCHED BY THE CHAIN
            IF (G4 .LE. BESTG) GOTO 270
            IF (IT6 .LE. NP2) THEN
               DNR = DNB(1, IT6)
            ELSE
               DNR = DENB(1, IT6 - NP2)
            END IF
            IF (G4 - 1.0D-6 .LT. DNR) GOTO 270
            IF (KADD(IT5) .EQ. ICHN) GOTO 270
            CALL CMLCL3(IP1, IP2, IP3, IP4, IP5, IP6, ITYP,
     1                  IBA, IBB, IBC)
            IF (ITYP .EQ. 0) GOTO 270
            BESTG = G4
            JB3 = IT3
            JB4 = IT4
            JB5 = IT5
            JB6 = IT6
            JTYP = ITYP
            JBA = IBA
            JBB = IBB
            JBC = IBC
  270       CONTINUE
  280    CONTINUE
  290    CONTINUE
  300 CONTINUE
  310 CONTINUE
      KWORK = KWORK + NEV
C     ---- NO STEP CLOSES: MAKE THE BEST ONE AND GO ON FROM ITS T6 -----
      IF (JB6 .EQ. 0 .OR. NDEP .GE. MXDEP) GOTO 850
      IF (KWORK .GT. KWMAX) GOTO 850
C     THE SIX ENDS' MOVES ARE NOW TOUCHED BY THIS CHAIN
      KADD(IT1) = ICHN
      KADD(IT2) = ICHN
      KADD(JB3) = ICHN
      KADD(JB4) = ICHN
      KADD(JB5) = ICHN
      KADD(JB6) = ICHN
      CALL CMLMV(JTYP, JBA, JBB, JBC, KR1, KR2, NREV)
      KTCH(NTCH + 1) = IT2
      KTCH(NTCH + 2) = JB3
      KTCH(NTCH + 3) = JB4
      KTCH(NTCH + 4) = JB5
      NTCH = NTCH + 4
      IT2 = JB6
      G0 = BESTG
      IP1 = CMLPS(IT1)
      IP2 = CMLPS(IT2)
      GOTO 100
C     ---- A SHORTER TOUR: QUEUE THE ITEMS WHOSE MOVES CHANGED (T1'S
C     ITEM M IS LOOKED AT AGAIN BY CMOPT2) -----------------------------
  800 CONTINUE
      DGAIN = DGAIN + GAIN
      LIMP = 1
      DO 810 L = 1, NTCH
         IF (KTCH(L) .LE. NP2) CALL CMQPSH((KTCH(L) + 1) / 2)
  810 CONTINUE
      RETURN
C     ---- NO SHORTER TOUR: UNDO THE CHAIN -----------------------------
  850 CONTINUE
      DO 860 I = NREV, 1, -1
         CALL CMTREV(KR1(I), KR2(I))
  860 CONTINUE
  900 CONTINUE
      RETURN
C     END OF CMLK3
      END
