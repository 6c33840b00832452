C=======================================================================
C     CMLK3  - LIN AND KERNIGHAN'S CHAIN OF 3-OPT MOVES        (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMTOUR). THE TOUR IS SEEN AS A CYCLE
C              OF ENDS: THE TOOL'S START (PLACE 0), THE ENTRY AND EXIT
C              OF EACH ITEM IN TOUR ORDER, THE START POINT, AND BACK TO
C              THE TOOL'S START; THE MOVE INSIDE AN ITEM AND THE ONE
C              FROM THE START POINT BACK TO THE TOOL'S START ARE FIXED.
C              T1 IS AN END OF ITEM M AND T2 ITS NEIGHBOUR ACROSS A
C              MOVE. A STEP TAKES OUT THE MOVES T1-T2, T3-T4, T5-T6 AND
C              PUTS IN T2-T3, T4-T5, T6-T1, WHERE T3 IS A NEAR END OF
C              T2 (KNB) AND T5 ONE OF T4, EACH NEARER THAN WHAT THE
C              STEP HAS GAINED SO FAR (THE GAIN CRITERION). A 2-OPT OR
C              3-OPT MOVE THAT SHORTENS THE TOUR IS MADE AT ONCE AND
C              ENDS THE CHAIN; ELSE THE BEST 3-OPT MOVE IS MADE AND
C              THE CHAIN GOES ON FROM T1 AND T6, NEVER TAKING OUT A
C              MOVE IT PUT IN, FOR AT MOST MXDEP STEPS. A CHAIN THAT
C              ENDS WITHOUT A SHORTER TOUR IS UNDONE. THIS IS THE STEP
C              OF HELSGAUN'S LKH (MOVE TYPE 3), DOCS/SOURCES.MD.
C     M       (INPUT)  INTEGER  THE ITEM WHOSE TWO ENDS ARE TRIED AS T1
C     LIMP    (OUTPUT) INTEGER  1 IF THE TOUR WAS CHANGED, ELSE 0
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
C     ---- /CMTWL/ THE CHAIN OF CMLK3 WHOSE MOVES PUT IN THE MOVE AT
C     EACH END (ITS NUMBER ICHN), SO NO CHAIN TAKES OUT WHAT IT PUT IN
      INTEGER ICHN, KADD(MXPT + 2)
      COMMON /CMTWL/ ICHN, KADD
      SAVE /CMTWL/
C     ---- LOCAL -------------------------------------------------------
      INTEGER MXDEP, MXREV, MXC
      PARAMETER (MXDEP = 50, MXREV = 3 * MXDEP, MXC = 8)
      INTEGER KR1(MXREV), KR2(MXREV), NREV, KTCH(6 * MXDEP + 6), NTCH,
     1        ISIDE, NP2, NDEP, IT1, IT2, IT3, IT4, IT5, IT6, IP1, IP2,
     2        IP3, IP4, IP5, IP6, IQ, IQ5, K3, K5, NC3, NC5, M3, M5,
     3        NR3, NR5, IR3, IR5, IX1, IY1, IX2, IY2, IX3, IY3, IX4,
     4        IY4, IX5, IY5, IX6, IY6, ITYP, IBA, IBB, IBC, JB3, JB4,
     5        JB5, JB6, JTYP, JBA, JBB, JBC, L, I, MM2, IDR, NCY, IR3P,
     6        IR4P, IR5P, IR6P, KREL, JPX
      LOGICAL LONE3, LONE5
      DOUBLE PRECISION G0, G1, G2, G3, G4, GAIN, BESTG, DQ, D45, DNR,
     1        DIST
      INTEGER CMLPS, CMLED
      INTEGER JX1, JY1, JX2, JY2
      INTEGER KIN, KOUT, MM
C     THE DISTANCE OF TWO POINTS: A STATEMENT FUNCTION, NO CALL
      DIST(JX1, JY1, JX2, JY2) = SQRT((DBLE(JX1) - JX2)**2 +
     1   (DBLE(JY1) - JY2)**2)
C     THE END ITEM MM IS ENTERED BY, AND THE END IT IS LEFT BY, AS IT
C     IS DRAWN NOW (CMEND'S RULE)
      KIN(MM) = 2 * MM - 1 + IORI(MM)
      KOUT(MM) = 2 * MM - IORI(MM)
C     THE PLACE OF THE CYCLE OF ENDS JPX COUNTED FROM T1 TOWARDS T2
      KREL(JPX) = MOD((JPX - IP1) * IDR + NCY, NCY)
C
      LIMP = 0
      NP2 = 2 * NITM
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
      IF (MOD(IP1, 2) .EQ. 0) THEN
         IP2 = IP1 + 1
      ELSE
         IP2 = IP1 - 1
      END IF
      IT2 = CMLED(IP2)
      IX1 = KQX(IT1)
      IY1 = KQY(IT1)
      CALL CMLXY(IT2, IX2, IY2)
      G0 = DIST(IX1, IY1, IX2, IY2)
      NDEP = 0
C     ---- ONE STEP OF THE CHAIN: THE BEST 3-OPT MOVE FROM T1, T2 ------
  100 CONTINUE
      NDEP = NDEP + 1
      NCY = NP2 + 2
      IDR = IP2 - IP1
      BESTG = -1.0D30
      JB6 = 0
      IF (IT2 .LE. NP2) THEN
         NC3 = MXC
      ELSE
         NC3 = MIN(MXC, NENB(IT2 - NP2))
      END IF
      DO 300 K3 = 1, NC3
         IF (IT2 .LE. NP2) THEN
            IQ = KNB(K3, IT2)
            DQ = DNB(K3, IT2)
         ELSE
            IQ = KENB(K3, IT2 - NP2)
            DQ = DENB(K3, IT2 - NP2)
         END IF
         IF (IQ .EQ. 0) GOTO 310
         G1 = G0 - DQ
         IF (G1 .LE. 1.0D-6) GOTO 310
         M3 = (IQ + 1) / 2
         LONE3 = KQX(2*M3) .EQ. KQX(2*M3-1) .AND.
     1           KQY(2*M3) .EQ. KQY(2*M3-1)
         NR3 = 1
         IF (LONE3) NR3 = 2
         DO 290 IR3 = 1, NR3
            IT3 = IQ
            IF (LONE3) IT3 = 2 * M3 - 2 + IR3
            IF (KADD(IT3) .EQ. ICHN) GOTO 290
            IF (IT3 .EQ. 2 * M3 - 1 + IORI(M3)) THEN
               IP3 = 2 * IPOS(M3) - 1
            ELSE
               IP3 = 2 * IPOS(M3)
            END IF
            IF (IP3 .EQ. IP1) GOTO 290
            IF (MOD(IP3, 2) .EQ. 0) THEN
               IP4 = IP3 + 1
            ELSE
               IP4 = IP3 - 1
            END IF
            IF (IP3 / 2 .EQ. IP1 / 2) GOTO 290
            IR3P = KREL(IP3)
            IR4P = KREL(IP4)
            IT4 = CMLED(IP4)
            IX3 = KQX(IT3)
            IY3 = KQY(IT3)
            CALL CMLXY(IT4, IX4, IY4)
            G2 = G1 + DIST(IX3, IY3, IX4, IY4)
C           ---- THE 2-OPT MOVE THAT CLOSES AT T4 ----------------------
            CALL CMLCL2(IP1, IP2, IP3, IP4, ITYP, IBA, IBB)
            IF (ITYP .EQ. 5) THEN
               GAIN = G2 - DIST(IX4, IY4, IX1, IY1)
               IF (GAIN .GT. 1.0D-6) THEN
                  CALL CMLMV(ITYP, IBA, IBB, IBB, KR1, KR2, NREV)
                  NTCH = NTCH + 1
                  KTCH(NTCH) = IT2
                  NTCH = NTCH + 1
                  KTCH(NTCH) = IT3
                  NTCH = NTCH + 1
                  KTCH(NTCH) = IT4
                  GOTO 800
               END IF
            END IF
C           ---- T5 A NEAR END OF T4, T6 BESIDE IT ---------------------
            IF (IT4 .LE. NP2) THEN
               NC5 = MXC
            ELSE
               NC5 = MIN(MXC, NENB(IT4 - NP2))
            END IF
            DO 280 K5 = 1, NC5
               IF (IT4 .LE. NP2) THEN
                  IQ5 = KNB(K5, IT4)
                  D45 = DNB(K5, IT4)
               ELSE
                  IQ5 = KENB(K5, IT4 - NP2)
                  D45 = DENB(K5, IT4 - NP2)
               END IF
               IF (IQ5 .EQ. 0) GOTO 285
               G3 = G2 - D45
               IF (G3 .LE. 1.0D-6) GOTO 285
               M5 = (IQ5 + 1) / 2
               LONE5 = KQX(2*M5) .EQ. KQX(2*M5-1) .AND.
     1                 KQY(2*M5) .EQ. KQY(2*M5-1)
               NR5 = 1
               IF (LONE5) NR5 = 2
               DO 270 IR5 = 1, NR5
                  IT5 = IQ5
                  IF (LONE5) IT5 = 2 * M5 - 2 + IR5
                  IF (KADD(IT5) .EQ. ICHN) GOTO 270
C                 (CMLPS, CMLED, CMLXY WRITTEN OUT: THE INNERMOST LOOP)
                  IF (IT5 .EQ. 2 * M5 - 1 + IORI(M5)) THEN
                     IP5 = 2 * IPOS(M5) - 1
                     IP6 = IP5 - 1
                  ELSE
                     IP5 = 2 * IPOS(M5)
                     IP6 = IP5 + 1
                  END IF
                  IF (IP5 .EQ. IP3) GOTO 270
                  IF (IP5 / 2 .EQ. IP1 / 2 .OR. IP5 / 2 .EQ. IP3 / 2)
     1               GOTO 270
C                 WHETHER THE SIX ENDS MAKE A TOUR, AS LKH FINDS IT:
C                 WITH T4 BEFORE T3 (THE 2-OPT MOVE CLOSES) T6 MUST BE
C                 AFTER T5 IF T5 LIES FROM T2 TO T4, ELSE BEFORE IT;
C                 WITH T4 AFTER T3, T5 MUST LIE FROM T2 TO T3
                  IR5P = KREL(IP5)
                  IR6P = KREL(IP6)
                  IF (IR4P .EQ. IR3P - 1) THEN
                     IF (IR5P .LE. IR4P) THEN
                        IF (IR6P .NE. IR5P + 1) GOTO 270
                     ELSE
                        IF (IR6P .NE. IR5P - 1) GOTO 270
                     END IF
                  ELSE
                     IF (IR5P .GT. IR3P .OR. IR6P .EQ. 0) GOTO 270
                  END IF
                  IF (IP6 .EQ. 0) THEN
                     IT6 = NP2 + 1
                     IX6 = KDSX
                     IY6 = KDSY
                  ELSE IF (IP6 .EQ. NP2 + 1) THEN
                     IT6 = NP2 + 2
                     IX6 = KDTX
                     IY6 = KDTY
                  ELSE
                     IF (MOD(IP6, 2) .EQ. 1) THEN
                        MM2 = ITOUR((IP6 + 1) / 2)
                        IT6 = 2 * MM2 - 1 + IORI(MM2)
                     ELSE
                        MM2 = ITOUR(IP6 / 2)
                        IT6 = 2 * MM2 - IORI(MM2)
                     END IF
                     IX6 = KQX(IT6)
                     IY6 = KQY(IT6)
                  END IF
                  IX5 = KQX(IT5)
                  IY5 = KQY(IT5)
                  G4 = G3 + DIST(IX5, IY5, IX6, IY6)
C                 THE MOVE CLOSES SHORTER IF T6-T1 IS SHORTER THAN G4:
C                 SQUARES FIRST, THE ROOT ONLY THEN
                  GAIN = 0.0D0
                  IF (G4 .GT. 1.0D-6) THEN
                     IF ((DBLE(IX6) - IX1)**2 + (DBLE(IY6) - IY1)**2
     1                   .LT. (G4 - 1.0D-6)**2)
     2                  GAIN = G4 - DIST(IX6, IY6, IX1, IY1)
                  END IF
                  IF (GAIN .LE. 1.0D-6 .AND. G4 .LE. BESTG) GOTO 270
                  CALL CMLCL3(IP1, IP2, IP3, IP4, IP5, IP6, ITYP,
     1                        IBA, IBB, IBC)
                  IF (ITYP .EQ. 0) GOTO 270
                  IF (GAIN .GT. 1.0D-6) THEN
                     CALL CMLMV(ITYP, IBA, IBB, IBC, KR1, KR2, NREV)
                     NTCH = NTCH + 1
                     KTCH(NTCH) = IT2
                     NTCH = NTCH + 1
                     KTCH(NTCH) = IT3
                     NTCH = NTCH + 1
                     KTCH(NTCH) = IT4
                     NTCH = NTCH + 1
                     KTCH(NTCH) = IT5
                     NTCH = NTCH + 1
                     KTCH(NTCH) = IT6
                     GOTO 800
                  END IF
C                 THE BEST MOVE THAT DOES NOT CLOSE: ITS GAIN MUST STAY
C                 ABOVE THE NEAREST END OF T6, OR NO NEXT STEP CAN GAIN
                  IF (G4 .LE. BESTG) GOTO 270
                  IF (IT6 .LE. NP2) THEN
                     DNR = DNB(1, IT6)
                  ELSE
                     DNR = DENB(1, IT6 - NP2)
                  END IF
                  IF (G4 - 1.0D-6 .LT. DNR) GOTO 270
                  BESTG = G4
                  JB3 = IT3
                  JB4 = IT4
                  JB5 = IT5
                  JB6 = IT6
                  JTYP = ITYP
                  JBA = IBA
                  JBB = IBB
                  JBC = IBC
  270          CONTINUE
  280       CONTINUE
  285       CONTINUE
  290    CONTINUE
  300 CONTINUE
  310 CONTINUE
C     ---- NO MOVE CLOSES: MAKE THE BEST ONE AND GO ON FROM ITS T6 -----
      IF (JB6 .EQ. 0 .OR. NDEP .GE. MXDEP) GOTO 850
      IF (NJRN .GT. MXJRN - 6 .OR. KWORK .GT. KWMAX) GOTO 850
      CALL CMLMV(JTYP, JBA, JBB, JBC, KR1, KR2, NREV)
      KADD(IT2) = ICHN
      KADD(JB3) = ICHN
      KADD(JB4) = ICHN
      KADD(JB5) = ICHN
      NTCH = NTCH + 1
      KTCH(NTCH) = IT2
      NTCH = NTCH + 1
      KTCH(NTCH) = JB3
      NTCH = NTCH + 1
      KTCH(NTCH) = JB4
      NTCH = NTCH + 1
      KTCH(NTCH) = JB5
      IT2 = JB6
      G0 = BESTG
      IP1 = CMLPS(IT1)
      IP2 = CMLPS(IT2)
      CALL CMLXY(IT2, IX2, IY2)
      GOTO 100
C     ---- THE CHAIN CLOSED SHORTER: KEEP IT, QUEUE THE ITEMS ---------
  800 CONTINUE
      DGAIN = DGAIN + GAIN
      LIMP = 1
      DO 810 L = 1, NTCH
         IF (KTCH(L) .LE. NP2) THEN
            MM2 = (KTCH(L) + 1) / 2
            CALL CMQPSH(MM2)
         END IF
  810 CONTINUE
      RETURN
C     ---- NO SHORTER TOUR: UNDO THE CHAIN'S MOVES, LAST FIRST ---------
  850 CONTINUE
      DO 860 I = NREV, 1, -1
         CALL CMTREV(KR1(I), KR2(I))
  860 CONTINUE
  900 CONTINUE
      RETURN
C     END OF CMLK3
      END
