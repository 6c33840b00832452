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
C              WITH THE ONE OR TWO AFTER IT, ELSEWHERE. ITEMS ARE TAKEN
C              FROM A QUEUE; AN ITEM WHOSE NEIGHBOURS CHANGE GOES BACK
C              ON IT. ROUND 1 IS 2-OPT ALONE; EACH FURTHER ROUND (AT
C              MOST 10) QUEUES EVERY ITEM AGAIN AND ADDS OR-OPT, UNTIL A
C              ROUND MAKES NO MOVE OR THE WORK BOUND IS REACHED.
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
C     ---- LOCAL -------------------------------------------------------
      INTEGER M, IP, J, K, IE, IQ, M2, IA, IB, ISIDE, LIMP, NROUND,
     1        NMOVE, IX2, IY2, IX4, IY4, IE4
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
         D1 = DIST(KQX(IE), KQY(IE), IX2, IY2)
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
C           BESIDE IQ; IN: THE MOVES IE-IQ AND (IX2,IY2)-(IX4,IY4)
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
            GAIN = D1 + DIST(KQX(IQ), KQY(IQ), IX4, IY4)
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
C     ---- NO 2-OPT MOVE: TRY MOVING THE ITEM ELSEWHERE ----------------
      LIMP = 0
      IF (NROUND .GT. 1) CALL CMOROP(M, LIMP)
      NMOVE = NMOVE + LIMP
      IF (LIMP .EQ. 1 .AND. KWORK .LE. KWMAX) GOTO 25
      GOTO 20
C     END OF CMOPT2
      END
