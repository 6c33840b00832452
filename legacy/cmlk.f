C=======================================================================
C     CMLK   - SHORTEN THE TOUR BY LIN-KERNIGHAN MOVES AND KICKS
C                                                               (SHARED)
C     SOURCE:  S. LIN, B. W. KERNIGHAN, OPERATIONS RESEARCH 21 (1973)
C              498-516 (THE MOVES: CMLKST); THE KICKS OF CMLKK.
C              THE TOUR OF CMTOUR (A PATH FROM THE TOOL'S PLACE
C              THROUGH THE ITEMS TO THE START POINT) IS WRITTEN AS A
C              CYCLE OF ENDS: THE TOOL'S PLACE S, EACH ITEM'S ENTRY AND
C              EXIT (ONE END FOR AN ITEM WHOSE ENTRY AND EXIT ARE ONE
C              POINT, WHICH IS THEN DRAWN FORWARD), THE START POINT T,
C              AND BACK TO S. THE MOVE INSIDE AN ITEM (ENTRY-EXIT) AND
C              THE MOVE T-S ARE FIXED: NO MOVE TAKES THEM OUT, SO THE
C              CYCLE, READ FROM S AWAY FROM T, IS ALWAYS A TOUR. END
C              2I-1 IS ITEM I'S ENTRY DRAWN FORWARD, 2I ITS EXIT; S IS
C              END 2*NITM+1, T END 2*NITM+2.
C     NKICK   (INPUT)  INTEGER  THE NUMBER OF KICKS (CMLKK)
C     THE TOUR IN /CMITM/ (ITOUR, IPOS, IORI) IS READ AND REPLACED;
C     KNB MUST HOLD THE NEAR ENDS OF EVERY END (CMKNN).
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMLK(NKICK)
      IMPLICIT NONE
      INTEGER NKICK
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
      INTEGER IS, IT, IP, M, N, K, INC, NPOS
C
      IS = 2 * NITM + 1
      IT = 2 * NITM + 2
C     ---- THE CYCLE: S, THE ITEMS IN TOUR ORDER, T -------------------
      NLN = 1
      LTR(1) = IS
      LMT(IS) = IT
      DO 10 IP = 1, NITM
         M = ITOUR(IP)
         IF (KQX(2*M) .EQ. KQX(2*M-1) .AND.
     1       KQY(2*M) .EQ. KQY(2*M-1)) THEN
            NLN = NLN + 1
            LTR(NLN) = 2 * M - 1
            LMT(2 * M - 1) = 0
         ELSE
            LTR(NLN + 1) = 2 * M - 1 + IORI(M)
            LTR(NLN + 2) = 2 * M - IORI(M)
            LMT(2 * M - 1) = 2 * M
            LMT(2 * M) = 2 * M - 1
            NLN = NLN + 2
         END IF
   10 CONTINUE
      NLN = NLN + 1
      LTR(NLN) = IT
      LMT(IT) = IS
      DO 15 IP = 1, NLN
         LPS(LTR(IP)) = IP
         LQF(LTR(IP)) = 0
   15 CONTINUE
C     ---- LIN-KERNIGHAN FROM EVERY END, THEN THE KICKS ----------------
      LQH = 1
      LQN = 0
      DO 20 IP = 1, NLN
         CALL CMLQP(LTR(IP))
   20 CONTINUE
      NJRN = 0
      LJRN = 0
      DGAIN = 0.0D0
      CALL CMLKQ(0)
      CALL CMLKK(NKICK)
C     ---- BACK TO THE TOUR OF ITEMS: FROM S, AWAY FROM T --------------
      IP = LPS(IS)
      INC = 1
      IF (LTR(MOD(IP, NLN) + 1) .EQ. IT) INC = -1
      NPOS = 0
   30 CONTINUE
      IP = MOD(IP + INC - 1 + NLN, NLN) + 1
      N = LTR(IP)
      IF (N .EQ. IT) GOTO 40
      M = (N + 1) / 2
      NPOS = NPOS + 1
      ITOUR(NPOS) = M
      IPOS(M) = NPOS
      IORI(M) = 0
      IF (LMT(N) .NE. 0) THEN
C        THE ITEM'S OTHER END FOLLOWS: ENTERED BY ITS EXIT, IT IS
C        DRAWN BACKWARDS
         IF (N .EQ. 2 * M) IORI(M) = 1
         IP = MOD(IP + INC - 1 + NLN, NLN) + 1
      END IF
      GOTO 30
   40 CONTINUE
      RETURN
C     END OF CMLK
      END
