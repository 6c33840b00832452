C=======================================================================
C     CMRUNM - MOVE A RUN OF THE TOUR ELSEWHERE BY THREE REVERSALS
C                                                               (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMOROP, CMOR3). THE ITEMS AT PLACES
C              I..J2 ARE TAKEN OUT AND PUT BETWEEN THE ITEMS NOW AT
C              PLACES IBC AND IBC+1, IN THEIR ORDER AND DIRECTION OR
C              TURNED ROUND. RUN S AND THE ITEMS R BETWEEN IT AND ITS
C              NEW PLACE: S R BECOMES R S BY REVERSING S (UNLESS IT IS
C              TO BE TURNED ROUND), R, THEN BOTH; LIKEWISE R S.
C     I, J2   (INPUT)  INTEGER  THE RUN, 1 .LE. I .LE. J2 .LE. NITM
C     IBC     (INPUT)  INTEGER  THE PLACE AFTER WHICH IT GOES, 0..NITM,
C                               NOT I-1..J2
C     IBREV   (INPUT)  INTEGER  1 TO TURN THE RUN ROUND, ELSE 0
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMRUNM(I, J2, IBC, IBREV)
      IMPLICIT NONE
      INTEGER I, J2, IBC, IBREV
C
      IF (IBC .GT. J2) THEN
         IF (IBREV .EQ. 0) CALL CMTREV(I, J2)
         CALL CMTREV(J2 + 1, IBC)
         CALL CMTREV(I, IBC)
      ELSE
         CALL CMTREV(IBC + 1, I - 1)
         IF (IBREV .EQ. 0) CALL CMTREV(I, J2)
         CALL CMTREV(IBC + 1, J2)
      END IF
      RETURN
C     END OF CMRUNM
      END
