C=======================================================================
C     CMOPT2 - IMPROVE THE TOUR BY 2-OPT AND OR-OPT MOVES     (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMTOUR). A 2-OPT MOVE TAKES OUT THE
C              MOVES AFTER PLACES A AND B (A .LT. B) AND PUTS IN THE
C              MOVES EXIT(A)-EXIT(B) AND ENTRY(A+1)-ENTRY(B+1): THE
C              ITEMS AT A+1..B ARE THEN DRAWN IN REVERSE ORDER AND
C              DIRECTION. A NEW MOVE EXIT-EXIT IS ONLY TRIED TOWARDS ONE
C              OF THE NEAREST ENDS (KNB), AND ONLY IF SHORTER THAN THE
C              MOVE IT REPLACES; LIKEWISE ENTRY-ENTRY. WHEN NO 2-OPT
C              MOVE HELPS AN ITEM, OR-OPT (CMOROP) TRIES TO MOVE IT,
C              WITH THE ONE OR TWO AFTER IT, ELSEWHERE, AND IN A PACKAGE
C              OF AT MOST 20000 ITEMS, FROM A NEW TOUR, LIN AND
C              KERNIGHAN'S CHAIN OF 3-OPT MOVES (CMLK3) FROM IT, IN THE
C              REPAIR OF A KICK OR-3OPT (CMOR3), A RUN OF ANY LENGTH
C              MOVED. THE FIRST AND LAST ITEMS ALSO TRY THE
C              2-OPT MOVES SEEN FROM THE TOOL'S START AND THE START
C              POINT, WHICH HAVE NEAR ENDS OF THEIR OWN (CMKDEP) BUT ARE
C              NOT ITEMS: WITHOUT THEM A START POINT OFF THE PADS KEPT
C              ITS LONG MOVES TILL A KICK HAPPENED TO CUT THEM. ITEMS
C              ARE TAKEN FROM A QUEUE; AN ITEM WHOSE NEIGHBOURS CHANGE
C              GOES BACK ON IT. ROUND 1 IS 2-OPT ALONE; EACH FURTHER
C              ROUND (AT MOST 10) QUEUES EVERY ITEM AGAIN AND ADDS
C              OR-OPT, UNTIL A ROUND MAKES NO MOVE OR THE WORK BOUND IS
C              REACHED. WITH THE CHAIN ROUND 2 IS THE LAST: ITS QUEUE
C              HAS LOOKED AT EVERY ITEM AGAIN WHOSE MOVES CHANGED, AND A
C              THIRD ROUND OF CHAINS FROM EVERY ITEM COST A THIRD MORE
C              TIME FOR TOURS HARDLY SHORTER (DOCS/PERFORMANCE.MD).
C     IMODE   (INPUT)  INTEGER  0 = THE ROUNDS ABOVE, FROM A NEW TOUR;
C                               1 = ONLY THE ITEMS ALREADY QUEUED AND
C                               THOSE THEIR MOVES QUEUE, 2-OPT AND
C                               OR-OPT, TILL THE QUEUE IS EMPTY
C                               (CMKICK); 2 = AS 1, AND EACH ITEM FROM
C                               THE QUEUE ADDS 50 TO THE WORK KWORK
C     THE LENGTH THE MOVES TAKE OFF THE TOUR IS ADDED TO DGAIN.
C     THE END BESIDE A PLACE IS LOOKED UP HERE (AND IN CMOROP) AS
C     CMEND DOES IT, WRITTEN OUT: KIN(M) = 2M-1+IORI(M) IS THE END ITEM
C     M IS ENTERED BY, KOUT(M) = 2M-IORI(M) THE ONE IT IS LEFT BY; PLACE
C     0 IS THE TOOL'S START, NITM+1 THE START POINT. A CALL OF CMEND PER
C     LOOK-UP TOOK A SEVENTH OF A 1173-ITEM TAPE'S INSTRUCTIONS.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMOPT2(IMODE)
      IMPLICIT NONE
      INTEGER IMODE
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
      LOGICAL LCHAIN
      INTEGER M, IP, J, K, IE, IQ, IQ4, M2, IA, IB, ISIDE, LIMP,
     1        NROUND, NMOVE, IX2, IY2, IX4, IY4, IE4, IX3, IY3
      DOUBLE PRECISION D1, DQ, GAIN, DIST
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
C     THE CHAIN (CMLK3): FROM A NEW TOUR, IN A PACKAGE OF AT MOST 20000
C     ITEMS
      LCHAIN = IMODE .EQ. 0 .AND. NJOB .LE. 20000
      NROUND = 0
      IF (IMODE .GE. 1) THEN
         NROUND = 2
         NMOVE = 0
         GOTO 20
      END IF
C     ---- EVERY ITEM IN THE QUEUE, IN TOUR ORDER ---------------------
    5 CONTINUE
      NROUND = NROUND + 1
      NMOVE = 0
      DO 10 IP = 1, NITM
         KQUE(IP) = ITOUR(IP)
         LQUE(ITOUR(IP)) = 1
   10 CONTINUE
      KQHD = 1
      KQN = NITM
C     ---- TAKE THE NEXT ITEM ------------------------------------------
   20 CONTINUE
      IF (KWORK .GT. KWMAX) RETURN
      IF (KQN .EQ. 0) THEN
         IF (IMODE .GE. 1) RETURN
         IF ((NMOVE .EQ. 0 .AND. NROUND .GT. 1) .OR. NROUND .GE. 10)
     1      RETURN
         IF (NROUND .GE. 2 .AND. LCHAIN) RETURN
         GOTO 5
      END IF
      M = KQUE(KQHD)
      KQHD = MOD(KQHD, NITM) + 1
      KQN = KQN - 1
      LQUE(M) = 0
      IF (IMODE .EQ. 2) KWORK = KWORK + 50
   25 CONTINUE
C     A KICK'S REPAIR STOPS BEFORE MXJRN REVERSALS (A MOVE MAKES AT
C     MOST THREE): A BOUND ON ONE REPAIR, BESIDE THE KICKS' WORK BOUND
      IF (IMODE .GE. 1 .AND. NJRN .GT. MXJRN - 3) RETURN
      DO 60 ISIDE = 1, 2
         IP = IPOS(M)
         IF (ISIDE .EQ. 1) THEN
C           THE MOVE LEAVING M: EXIT(IP) TO ENTRY(IP+1)
            IE = KOUT(M)
            IF (IP .LT. NITM) THEN
               IE4 = KIN(ITOUR(IP + 1))
               IX2 = KQX(IE4)
               IY2 = KQY(IE4)
            ELSE
               IX2 = KDTX
               IY2 = KDTY
            END IF
         ELSE
C           THE MOVE INTO M: EXIT(IP-1) TO ENTRY(IP)
            IE = KIN(M)
            IF (IP .GT. 1) THEN
               IE4 = KOUT(ITOUR(IP - 1))
               IX2 = KQX(IE4)
               IY2 = KQY(IE4)
            ELSE
               IX2 = KDSX
               IY2 = KDSY
            END IF
         END IF
C        ITS LENGTH, AS OF EVERY MOVE TAKEN OUT, FROM DMV (CMDMV)
         D1 = DMV(IE)
         DO 50 K = 1, MXNB
            IQ = KNB(K, IE)
            IF (IQ .EQ. 0) GOTO 60
            DQ = DNB(K, IE)
            IF (DQ .GE. D1 - 1.0D-6) GOTO 60
            M2 = (IQ + 1) / 2
C           IQ MUST BE THE SAME KIND OF END OF ITS ITEM AS IE IS OF M
C           (AN ITEM WHOSE ENDS ARE ONE POINT HAS BOTH KINDS THERE)
            IF (KQX(2*M2) .NE. KQX(2*M2-1) .OR.
     1          KQY(2*M2) .NE. KQY(2*M2-1)) THEN
               IF (ISIDE .EQ. 1 .AND. IQ .NE. KOUT(M2)) GOTO 50
               IF (ISIDE .EQ. 2 .AND. IQ .NE. KIN(M2))
     1            GOTO 50
            END IF
            J = IPOS(M2)
            IA = MIN(IP, J)
            IB = MAX(IP, J)
            IF (ISIDE .EQ. 2) THEN
               IA = IA - 1
               IB = IB - 1
            END IF
            IF (IA .EQ. IB) GOTO 50
C           OUT: THE MOVES IE-(IX2,IY2) AND IQ-(IX4,IY4), THE END
C           BESIDE IQ (THE MOVE OF IQ4, THE END OF M2 ON THAT SIDE);
C           IN: THE MOVES IE-IQ AND (IX2,IY2)-(IX4,IY4)
            IF (ISIDE .EQ. 1) THEN
               IF (J .LT. NITM) THEN
                  IE4 = KIN(ITOUR(J + 1))
                  IX4 = KQX(IE4)
                  IY4 = KQY(IE4)
               ELSE
                  IX4 = KDTX
                  IY4 = KDTY
               END IF
            ELSE
               IF (J .GT. 1) THEN
                  IE4 = KOUT(ITOUR(J - 1))
                  IX4 = KQX(IE4)
                  IY4 = KQY(IE4)
               ELSE
                  IX4 = KDSX
                  IY4 = KDSY
               END IF
            END IF
            IF (ISIDE .EQ. 1) THEN
               IQ4 = KOUT(M2)
            ELSE
               IQ4 = KIN(M2)
            END IF
            GAIN = D1 + DMV(IQ4)
     1           - DQ - DIST(IX2, IY2, IX4, IY4)
            IF (GAIN .LE. 1.0D-6) GOTO 50
C           ---- TAKE THE MOVE; LOOK AGAIN AT THE FOUR ITEMS CONCERNED -
            CALL CMTREV(IA + 1, IB)
            DGAIN = DGAIN + GAIN
            NMOVE = NMOVE + 1
            IF (IA .GE. 1) CALL CMQPSH(ITOUR(IA))
            CALL CMQPSH(ITOUR(IA + 1))
            CALL CMQPSH(ITOUR(IB))
            IF (IB .LT. NITM) CALL CMQPSH(ITOUR(IB + 1))
            IF (KWORK .GT. KWMAX) RETURN
            GOTO 25
   50    CONTINUE
   60 CONTINUE
C     ---- THE FIRST OR LAST MOVE, FROM THE FIXED POINT'S SIDE ---------
C     (CMKDEP): THE LAST ITEM L, THE START POINT T AND AN ITEM Q AT J
C     WHOSE ENTRY IS NEAR T: REVERSING J..NITM JOINS THE ITEM BEFORE
C     Q TO L AND Q TO T. LIKEWISE THE FIRST ITEM, THE TOOL'S START
C     AND AN ITEM WHOSE EXIT IS NEAR IT, REVERSING 1..J.
      IP = IPOS(M)
      IF (IP .EQ. NITM) THEN
         IE = KOUT(M)
         D1 = DMV(IE)
         DO 70 K = 1, NENB(2)
            IQ = KENB(K, 2)
            DQ = DENB(K, 2)
            IF (DQ .GE. D1 - 1.0D-6) GOTO 80
            M2 = (IQ + 1) / 2
            IF (KQX(2*M2) .NE. KQX(2*M2-1) .OR.
     1          KQY(2*M2) .NE. KQY(2*M2-1)) THEN
               IF (IQ .NE. KIN(M2)) GOTO 70
            END IF
            J = IPOS(M2)
            IF (J .GE. NITM) GOTO 70
            IF (J .GT. 1) THEN
               IE4 = KOUT(ITOUR(J - 1))
               IX3 = KQX(IE4)
               IY3 = KQY(IE4)
            ELSE
               IX3 = KDSX
               IY3 = KDSY
            END IF
            GAIN = D1 + DMV(KIN(M2))
     1           - DQ - DIST(IX3, IY3, KQX(IE), KQY(IE))
            IF (GAIN .LE. 1.0D-6) GOTO 70
            CALL CMTREV(J, NITM)
            DGAIN = DGAIN + GAIN
            NMOVE = NMOVE + 1
            IF (J .GT. 1) CALL CMQPSH(ITOUR(J - 1))
            CALL CMQPSH(ITOUR(J))
            CALL CMQPSH(ITOUR(NITM))
            IF (KWORK .GT. KWMAX) RETURN
            GOTO 25
   70    CONTINUE
      END IF
   80 CONTINUE
      IF (IP .EQ. 1) THEN
         IE = KIN(M)
         D1 = DMV(IE)
         DO 90 K = 1, NENB(1)
            IQ = KENB(K, 1)
            DQ = DENB(K, 1)
            IF (DQ .GE. D1 - 1.0D-6) GOTO 100
            M2 = (IQ + 1) / 2
            IF (KQX(2*M2) .NE. KQX(2*M2-1) .OR.
     1          KQY(2*M2) .NE. KQY(2*M2-1)) THEN
               IF (IQ .NE. KOUT(M2)) GOTO 90
            END IF
            J = IPOS(M2)
            IF (J .LE. 1) GOTO 90
            IF (J .LT. NITM) THEN
               IE4 = KIN(ITOUR(J + 1))
               IX3 = KQX(IE4)
               IY3 = KQY(IE4)
            ELSE
               IX3 = KDTX
               IY3 = KDTY
            END IF
            GAIN = D1 + DMV(KOUT(M2))
     1           - DQ - DIST(KQX(IE), KQY(IE), IX3, IY3)
            IF (GAIN .LE. 1.0D-6) GOTO 90
            CALL CMTREV(1, J)
            DGAIN = DGAIN + GAIN
            NMOVE = NMOVE + 1
            CALL CMQPSH(ITOUR(1))
            CALL CMQPSH(ITOUR(J))
            IF (J .LT. NITM) CALL CMQPSH(ITOUR(J + 1))
            IF (KWORK .GT. KWMAX) RETURN
            GOTO 25
   90    CONTINUE
      END IF
  100 CONTINUE
C     ---- NO 2-OPT MOVE: TRY MOVING THE ITEM ELSEWHERE ----------------
      LIMP = 0
      IF (NROUND .GT. 1) CALL CMOROP(M, LIMP)
C     IN A PACKAGE OF AT MOST 20000 ITEMS ALSO THE CHAIN (CMLK3) FROM A
C     NEW TOUR, A RUN OF ANY LENGTH (CMOR3) IN A KICK'S REPAIR: EACH
C     MAKES THE ROUNDS OR THE REPAIR TWO TO FIVE TIMES AS DEAR, WHICH
C     THE 100000-PAD BOARDS' TIME CANNOT TAKE
      IF (NROUND .GT. 1 .AND. LIMP .EQ. 0 .AND. NJOB .LE. 20000) THEN
         IF (LCHAIN) THEN
            CALL CMLK3(M, LIMP)
         ELSE
            CALL CMOR3(M, LIMP)
         END IF
      END IF
      NMOVE = NMOVE + LIMP
      IF (LIMP .EQ. 1 .AND. KWORK .LE. KWMAX) GOTO 25
      GOTO 20
C     END OF CMOPT2
      END
