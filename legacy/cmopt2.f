C=======================================================================
C     CMOPT2 - IMPROVE THE TOUR BY 2-OPT MOVES                  (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMTOUR). A MOVE TAKES OUT THE MOVES
C              AFTER PLACES A AND B (A .LT. B) AND PUTS IN THE MOVES
C              EXIT(A)-EXIT(B) AND ENTRY(A+1)-ENTRY(B+1): THE ITEMS AT
C              A+1..B ARE THEN DRAWN IN REVERSE ORDER AND DIRECTION.
C              A NEW MOVE EXIT-EXIT IS ONLY TRIED TOWARDS ONE OF THE
C              NEAREST ENDS (KNB), AND ONLY IF SHORTER THAN THE MOVE IT
C              REPLACES; LIKEWISE ENTRY-ENTRY.
C     CHANGES: 2026-11-22 FIRST RECONSTRUCTION
C=======================================================================
      SUBROUTINE CMOPT2
      IMPLICIT NONE
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
      PARAMETER (MXPT = 2 * MXITM, MXCEL = 2 * MXITM, MXNB = 8)
      INTEGER NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1        KQX(MXPT), KQY(MXPT), KCST(MXCEL + 1), KCCN(MXCEL),
     2        KCEL(MXPT), KSLT(MXPT), KNB(MXNB, MXPT), KQUE(MXITM),
     3        LQUE(MXITM)
      COMMON /CMTWK/ NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1               KQX, KQY, KCST, KCCN, KCEL, KSLT, KNB, KQUE, LQUE
C     ---- LOCAL -------------------------------------------------------
      INTEGER IHEAD, ITAIL, NQ, M, IP, J, K, IE, IQ, M2, IA, IB, ISIDE,
     1        IX1, IY1, IX2, IY2, IX3, IY3, IX4, IY4, NWORK, MXWORK, L
      DOUBLE PRECISION D1, DQ, GAIN, CMDST
      EXTERNAL CMDST
C
C     ---- EVERY ITEM IN THE QUEUE, IN TOUR ORDER ----------------------
      DO 10 IP = 1, NITM
         KQUE(IP) = ITOUR(IP)
         LQUE(ITOUR(IP)) = 1
   10 CONTINUE
      IHEAD = 1
      ITAIL = 0
      NQ = NITM
      NWORK = 0
      MXWORK = 50 * NITM + 100000
C     ---- TAKE THE NEXT ITEM ------------------------------------------
   20 CONTINUE
      IF (NQ .EQ. 0 .OR. NWORK .GT. MXWORK) RETURN
      M = KQUE(IHEAD)
      IHEAD = MOD(IHEAD, NITM) + 1
      NQ = NQ - 1
      LQUE(M) = 0
   25 CONTINUE
      DO 60 ISIDE = 1, 2
         IP = IPOS(M)
         IF (ISIDE .EQ. 1) THEN
C           THE MOVE LEAVING M: EXIT(IP) TO ENTRY(IP+1)
            IE = 2 * M - IORI(M)
            CALL CMEND(IP + 1, 2, IX2, IY2)
         ELSE
C           THE MOVE INTO M: EXIT(IP-1) TO ENTRY(IP)
            IE = 2 * M - 1 + IORI(M)
            CALL CMEND(IP - 1, 1, IX2, IY2)
         END IF
         D1 = CMDST(KQX(IE), KQY(IE), IX2, IY2)
         DO 50 K = 1, MXNB
            IQ = KNB(K, IE)
            IF (IQ .EQ. 0) GOTO 60
            DQ = CMDST(KQX(IE), KQY(IE), KQX(IQ), KQY(IQ))
            IF (DQ .GE. D1 - 1.0D-6) GOTO 60
            M2 = (IQ + 1) / 2
C           IQ MUST BE THE SAME KIND OF END OF ITS ITEM AS IE IS OF M
            IF (ISIDE .EQ. 1 .AND. IQ .NE. 2 * M2 - IORI(M2)) GOTO 50
            IF (ISIDE .EQ. 2 .AND. IQ .NE. 2 * M2 - 1 + IORI(M2))
     1         GOTO 50
            J = IPOS(M2)
            IA = MIN(IP, J)
            IB = MAX(IP, J)
            IF (ISIDE .EQ. 2) THEN
               IA = IA - 1
               IB = IB - 1
            END IF
            IF (IA .EQ. IB) GOTO 50
            CALL CMEND(IA, 1, IX1, IY1)
            CALL CMEND(IA + 1, 2, IX2, IY2)
            CALL CMEND(IB, 1, IX3, IY3)
            CALL CMEND(IB + 1, 2, IX4, IY4)
            GAIN = CMDST(IX1, IY1, IX2, IY2) + CMDST(IX3, IY3, IX4, IY4)
     1           - CMDST(IX1, IY1, IX3, IY3) - CMDST(IX2, IY2, IX4, IY4)
            IF (GAIN .LE. 1.0D-6) GOTO 50
C           ---- TAKE THE MOVE; LOOK AGAIN AT THE FOUR ITEMS CONCERNED -
            CALL CMTREV(IA + 1, IB)
            NWORK = NWORK + (IB - IA)
            DO 40 L = 1, 4
               IF (L .EQ. 1) J = IA
               IF (L .EQ. 2) J = IA + 1
               IF (L .EQ. 3) J = IB
               IF (L .EQ. 4) J = IB + 1
               IF (J .LT. 1 .OR. J .GT. NITM) GOTO 40
               M2 = ITOUR(J)
               IF (LQUE(M2) .EQ. 1 .OR. M2 .EQ. M) GOTO 40
               ITAIL = MOD(IHEAD + NQ - 1, NITM) + 1
               KQUE(ITAIL) = M2
               LQUE(M2) = 1
               NQ = NQ + 1
   40       CONTINUE
            IF (NWORK .GT. MXWORK) RETURN
            GOTO 25
   50    CONTINUE
   60 CONTINUE
      GOTO 20
C     END OF CMOPT2
      END
