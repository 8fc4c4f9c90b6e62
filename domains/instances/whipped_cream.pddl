; foon2pddl, encoding instances, level 3: 4 of 101 units after relevance pruning
; goal: whipped cream (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 7 (bowl 1, heavy cream 1, mixing bowl 1, spatula 1, sugar 1, whipped cream 1, whisk 1)
; lanes: each instance changes state only as in the unfolded plan
; subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)
(define (domain foon-instances-5a49eecd)
  (:requirements :strips :typing)
  (:types
    physical-object - object
    object-state - object
  )
  (:constants
    not-yet-made - object-state
    bowl_contains_whipped_cream - object-state
    bowl_empty - object-state
    heavy_cream_in_carton - object-state
    heavy_cream_in_mixing_bowl - object-state
    mixing_bowl_contains_heavy_cream - object-state
    mixing_bowl_contains_heavy_cream_sugar - object-state
    mixing_bowl_contains_whipped_cream - object-state
    mixing_bowl_empty - object-state
    spatula_plain - object-state
    sugar_granulated - object-state
    sugar_in_mixing_bowl - object-state
    whipped_cream_in_bowl_whipped - object-state
    whipped_cream_in_mixing_bowl_whipped - object-state
    whisk_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (occupied ?s - object-state)  ; some instance is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
    (lane ?x - physical-object ?s - object-state ?t - object-state)  ; static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)
    (together ?a - physical-object ?b - physical-object)  ; static: ?a and ?b change state in one firing of the unfolded plan
    (type_bowl ?x - physical-object)  ; ?x is of type bowl
    (type_heavy_cream ?x - physical-object)  ; ?x is of type heavy_cream
    (type_mixing_bowl ?x - physical-object)  ; ?x is of type mixing_bowl
    (type_spatula ?x - physical-object)  ; ?x is of type spatula
    (type_sugar ?x - physical-object)  ; ?x is of type sugar
    (type_whipped_cream ?x - physical-object)  ; ?x is of type whipped_cream
    (type_whisk ?x - physical-object)  ; ?x is of type whisk
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters (?mixing_bowl - physical-object ?heavy_cream - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_heavy_cream ?heavy_cream)
      (together ?mixing_bowl ?heavy_cream)
      (is ?mixing_bowl mixing_bowl_empty)
      (lane ?mixing_bowl mixing_bowl_empty mixing_bowl_contains_heavy_cream)
      (is ?heavy_cream heavy_cream_in_carton)
      (lane ?heavy_cream heavy_cream_in_carton heavy_cream_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?heavy_cream heavy_cream_in_mixing_bowl)
      (occupied heavy_cream_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_empty))
      (not (is ?heavy_cream heavy_cream_in_carton))
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters (?mixing_bowl - physical-object ?sugar - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_sugar ?sugar)
      (together ?mixing_bowl ?sugar)
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (lane ?mixing_bowl mixing_bowl_contains_heavy_cream mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_granulated)
      (lane ?sugar sugar_granulated sugar_in_mixing_bowl)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream))
      (not (is ?sugar sugar_granulated))
    )
  )

  (:action scoop_u16
    ; unit 16: scoop from 02-whipped_cream.foon:84
    ; scoop: mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spatula, bowl (empty) -> bowl (contains {whipped cream}), whipped cream (in [bowl], whipped), spatula
    :parameters (?whipped_cream - physical-object ?bowl - physical-object)
    :precondition (and
      (type_whipped_cream ?whipped_cream)
      (type_bowl ?bowl)
      (together ?whipped_cream ?bowl)
      (occupied mixing_bowl_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (lane ?whipped_cream whipped_cream_in_mixing_bowl_whipped whipped_cream_in_bowl_whipped)
      (occupied spatula_plain)
      (is ?bowl bowl_empty)
      (lane ?bowl bowl_empty bowl_contains_whipped_cream)
    )
    :effect (and
      (is ?whipped_cream whipped_cream_in_bowl_whipped)
      (occupied whipped_cream_in_bowl_whipped)
      (is ?bowl bowl_contains_whipped_cream)
      (occupied bowl_contains_whipped_cream)
      (not (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped))
      (not (is ?bowl bowl_empty))
    )
  )

  (:action whisk_u99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters (?mixing_bowl - physical-object ?whipped_cream - physical-object)
    :precondition (and
      (type_mixing_bowl ?mixing_bowl)
      (type_whipped_cream ?whipped_cream)
      (together ?mixing_bowl ?whipped_cream)
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (lane ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar mixing_bowl_contains_whipped_cream)
      (occupied heavy_cream_in_mixing_bowl)
      (occupied sugar_in_mixing_bowl)
      (occupied whisk_plain)
      (is ?whipped_cream not-yet-made)
      (lane ?whipped_cream not-yet-made whipped_cream_in_mixing_bowl_whipped)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_whipped_cream)
      (occupied mixing_bowl_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar))
      (not (is ?whipped_cream not-yet-made))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: whipped cream (in [bowl], whipped)
    :parameters ()
    :precondition (and
      (occupied whipped_cream_in_bowl_whipped)
    )
    :effect (and
      (goal-reached)
    )
  )
)
